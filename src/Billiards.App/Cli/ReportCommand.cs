using Billiards.Core.Scenes;
using System.CommandLine;
using System.Text;
using Billiards.App.Reports;

namespace Billiards.App.Cli;

/// <summary>
/// <c>report accuracy [--out DIR]</c>: the error-against-run-time report (CSV, SVG plot, Markdown
/// summary) with its cushion page; <c>report cushions [--out DIR]</c>: the cushion page alone.
/// </summary>
public static class ReportCommand
{
    /// <summary>The files the report writes into its folder.</summary>
    public static IReadOnlyList<string> FileNames { get; } = ["accuracy.csv", "accuracy.svg", "accuracy.md", .. CushionReport.FileNames];

    /// <summary>Builds the verb.</summary>
    public static Command Create(TextWriter stdout, TextWriter stderr)
    {
        var output = new Option<string>("--out") { Description = "Folder for accuracy.csv, accuracy.svg and accuracy.md.", DefaultValueFactory = _ => "out/accuracy" };
        var scenes = new Option<string?>("--scenes") { Description = "Folder of the scene suite (default: assets/scenes/accuracy)." };
        var accuracy = new Command("accuracy", "Measure each integrator and step against the event-based reference solver.") { output, scenes };
        accuracy.SetAction(parse =>
        {
            // Everything is checked before the first measurement: the suite, every scene in every
            // configuration measured, and the output folder.
            string folder = parse.GetValue(scenes) ?? AssetFolder.Scene("accuracy");
            if (string.IsNullOrWhiteSpace(folder))
            {
                throw new CliException("--scenes: the path is empty");
            }
            if (!Directory.Exists(folder))
            {
                throw new CliException($"--scenes {folder}: no such folder");
            }
            var files = Directory.GetFiles(folder, "*.json").Order(StringComparer.Ordinal).ToList();
            if (files.Count == 0)
            {
                throw new CliException($"--scenes {folder}: no scene files");
            }
            string dir = OutputFiles.CheckFolder("--out", parse.GetValue(output)!, [.. FileNames]);
            AccuracyReport.Validate(files);

            var rows = AccuracyReport.Measure(files, stderr);
            string summary = AccuracyReport.ToMarkdown(rows, files.Count);
            byte[][] contents =
            [
                Encoding.UTF8.GetBytes(AccuracyReport.ToCsv(rows)),
                Encoding.UTF8.GetBytes(AccuracyReport.ToSvg(rows)),
                Encoding.UTF8.GetBytes(summary),
                .. CushionReport.Files().Select(f => f.Bytes),
            ];
            Directory.CreateDirectory(dir);
            OutputFiles.WriteAll([.. FileNames.Select((name, i) => (Path.Combine(dir, name), contents[i]))]);
            stdout.Write(summary);
            return 0;
        });

        var cushionOutput = new Option<string>("--out") { Description = "Folder for cushions.md and its plots.", DefaultValueFactory = _ => "out/accuracy" };
        var cushions = new Command("cushions", "Draw the cushion models' rebounds side by side (the accuracy report's cushion page).") { cushionOutput };
        cushions.SetAction(parse =>
        {
            string dir = OutputFiles.CheckFolder("--out", parse.GetValue(cushionOutput)!, [.. CushionReport.FileNames]);
            var files = CushionReport.Files();
            Directory.CreateDirectory(dir);
            OutputFiles.WriteAll([.. files.Select(f => (Path.Combine(dir, f.Name), f.Bytes))]);
            stdout.WriteLine(string.Join(" ", files.Select(f => Path.Combine(dir, f.Name))));
            return 0;
        });
        return new Command("report", "Reports about the physics.") { accuracy, cushions };
    }
}
