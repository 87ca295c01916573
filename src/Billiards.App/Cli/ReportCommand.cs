using Billiards.Core.Scenes;
using System.CommandLine;
using System.Text;
using Billiards.App.Reports;

namespace Billiards.App.Cli;

/// <summary><c>report accuracy [--out DIR]</c>: the error-against-run-time report (CSV, SVG plot, Markdown summary).</summary>
public static class ReportCommand
{
    /// <summary>Builds the verb.</summary>
    public static Command Create(TextWriter stdout, TextWriter stderr)
    {
        var output = new Option<string>("--out") { Description = "Folder for accuracy.csv, accuracy.svg and accuracy.md.", DefaultValueFactory = _ => "out/accuracy" };
        var scenes = new Option<string?>("--scenes") { Description = "Folder of the scene suite (default: assets/scenes/accuracy)." };
        var accuracy = new Command("accuracy", "Measure each integrator and step against the event-based reference solver.") { output, scenes };
        accuracy.SetAction(parse =>
        {
            string folder = parse.GetValue(scenes) ?? AssetFolder.Scene("accuracy");
            if (!Directory.Exists(folder))
            {
                throw new CliException($"--scenes {folder}: no such folder");
            }
            var files = Directory.GetFiles(folder, "*.json").Order(StringComparer.Ordinal).ToList();
            if (files.Count == 0)
            {
                throw new CliException($"--scenes {folder}: no scene files");
            }
            string dir = parse.GetValue(output)!;
            var rows = AccuracyReport.Measure(files, stderr);
            Directory.CreateDirectory(dir);
            CommandLine.WriteAtomically(Path.Combine(dir, "accuracy.csv"), Encoding.UTF8.GetBytes(AccuracyReport.ToCsv(rows)));
            CommandLine.WriteAtomically(Path.Combine(dir, "accuracy.svg"), Encoding.UTF8.GetBytes(AccuracyReport.ToSvg(rows)));
            string summary = AccuracyReport.ToMarkdown(rows, files.Count);
            CommandLine.WriteAtomically(Path.Combine(dir, "accuracy.md"), Encoding.UTF8.GetBytes(summary));
            stdout.Write(summary);
            return 0;
        });
        return new Command("report", "Reports about the physics.") { accuracy };
    }
}
