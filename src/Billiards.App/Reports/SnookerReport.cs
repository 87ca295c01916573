using System.Globalization;
using System.Text;
using Billiards.Core.Ai;
using Billiards.Core.Physics;
using Billiards.Core.Table;

namespace Billiards.App.Reports;

/// <summary>
/// <c>report snookers</c>: the same seeded snookered 8-ball positions played by the computer
/// player without and with jump shots (<see cref="ShotPlanner.ConsiderJumps"/>), one thread and a
/// budget it never reaches, so a rerun prints the same table.
/// </summary>
public static class SnookerReport
{
    /// <summary>A budget no decision reaches (ms): the result depends on the seeds alone.</summary>
    public const int Budget = 600_000;

    /// <summary>Plays the positions both ways and returns the Markdown table.</summary>
    public static string Run(int positions, int level, int tries, ulong seed, TextWriter progress)
    {
        var table = TableSpec.FromPreset("pool-9ft");
        var physics = PhysicsParams.Default;
        var set = Snookers.Positions(table, physics.R, positions, seed);
        var budget = new PlannerBudget(Budget, Threads: 1);
        var rows = new List<(string Name, SnookerResult Result)>();
        foreach (bool jumps in new[] { false, true })
        {
            progress.WriteLine(jumps ? "with jump shots ..." : "without jump shots ...");
            var planner = new ShotPlanner(table, physics) { ConsiderJumps = jumps };
            rows.Add((jumps ? "with jumps" : "without jumps", Snookers.Measure(planner, set, level, tries, seed, budget)));
        }
        var c = CultureInfo.InvariantCulture;
        var sb = new StringBuilder();
        sb.AppendLine(c, $"Snookered 8-ball positions: {set.Count} (seed {seed}), level {level}, each decision struck {tries} times with the level's error");
        sb.AppendLine();
        sb.AppendLine("| planner | shots | no-contact fouls | all fouls | jump strokes chosen | below the cue's clearance |");
        sb.AppendLine("|---|---|---|---|---|---|");
        foreach (var (name, r) in rows)
        {
            sb.AppendLine(c, $"| {name} | {r.Shots} | {r.NoContact} ({100.0 * r.NoContact / r.Shots:0.0} %) | {r.Fouls} ({100.0 * r.Fouls / r.Shots:0.0} %) | {r.Jumps} of {r.Positions} | {r.Unplayable} |");
        }
        return sb.ToString();
    }
}
