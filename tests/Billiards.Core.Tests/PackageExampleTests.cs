using System.Diagnostics;
using System.Globalization;
using System.Text.RegularExpressions;
using Billiards.Core.Scenes;

namespace Billiards.Core.Tests;

/// <summary>
/// The example of the package README (src/Billiards.Core/README.md) cannot go stale: it is
/// samples/Billiards.Core.Example/Program.cs word for word, that project is built with the tests
/// (so a change of the API breaks the build), and running it prints what the engine computes
/// for its scene and what the README says it prints.
/// </summary>
public sealed partial class PackageExampleTests
{
    private static readonly string s_folder = Path.Combine(AppContext.BaseDirectory, "PackageExample");

    private static string Normalized(string text) => text.Replace("\r\n", "\n", StringComparison.Ordinal).Trim();

    /// <summary>The fenced blocks of the README after an opening fence with <paramref name="language"/> ("" for none).</summary>
    private static List<string> Blocks(string language)
    {
        var blocks = new List<string>();
        string[] lines = Normalized(File.ReadAllText(Path.Combine(s_folder, "README.md"))).Split('\n');
        for (int i = 0; i < lines.Length; i++)
        {
            if (lines[i].StartsWith("```", StringComparison.Ordinal))
            {
                int end = Array.IndexOf(lines, "```", i + 1);
                if (lines[i] == "```" + language)
                {
                    blocks.Add(string.Join('\n', lines[(i + 1)..end]));
                }
                i = end;
            }
        }
        return blocks;
    }

    private static string RunExample()
    {
        var start = new ProcessStartInfo("dotnet") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        start.ArgumentList.Add(Path.Combine(AppContext.BaseDirectory, "Billiards.Core.Example.dll"));
        using var process = Process.Start(start)!;
        var stderr = process.StandardError.ReadToEndAsync();
        string stdout = process.StandardOutput.ReadToEnd();
        Assert.True(process.WaitForExit(60_000), "the example did not finish");
        Assert.True(process.ExitCode == 0, stderr.Result);
        return Normalized(stdout);
    }

    [Fact]
    public void TheReadmeShowsTheExampleProgramWordForWord()
    {
        string program = Normalized(File.ReadAllText(Path.Combine(s_folder, "Program.cs")));
        Assert.Equal(program, Assert.Single(Blocks("csharp")));
    }

    [Fact]
    public void TheExamplePrintsTheEventsAndTheBallsAtRestOfItsScene()
    {
        string output = RunExample();

        // The same scene run here: the example's lines are its events and its balls at rest.
        string program = File.ReadAllText(Path.Combine(s_folder, "Program.cs"));
        int open = program.IndexOf("\"\"\"", StringComparison.Ordinal) + 3;
        string json = program[open..program.IndexOf("\"\"\"", open, StringComparison.Ordinal)];
        var sim = SimulationRunner.Run(SceneLoader.Parse(json, "example.json"), new RunOptions()).Simulation;
        Assert.True(sim.IsAtRest);

        string[] lines = output.Split('\n');
        var events = lines.Where(l => EventLine().IsMatch(l)).ToList();
        Assert.Equal(sim.Events.Count, events.Count);
        for (int i = 0; i < events.Count; i++)
        {
            var e = sim.Events[i];
            var m = EventLine().Match(events[i]);
            Assert.Equal(Math.Round(e.Time, 3), double.Parse(m.Groups[1].Value, CultureInfo.InvariantCulture));
            Assert.Equal(e.Kind.ToString(), m.Groups[2].Value);
        }
        Assert.Contains(events, l => l.Contains("BallPocket  1 at foot-left", StringComparison.Ordinal));
        for (int i = 0; i < sim.Ids.Count; i++)
        {
            var ball = sim.Balls[i];
            string expected = string.Create(CultureInfo.InvariantCulture, $"  {sim.Ids[i],-4} {ball.State,-10} ({ball.Position.X:0.000}, {ball.Position.Y:0.000}) m");
            Assert.Contains(expected, lines);
        }
    }

    [Fact]
    public void TheReadmeShowsWhatTheExamplePrints()
    {
        var plain = Blocks("");
        Assert.Contains(RunExample(), plain);
    }

    [GeneratedRegex(@"^(\d+\.\d{3}) s  (\w+)\s")]
    private static partial Regex EventLine();
}
