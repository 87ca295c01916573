using System.Globalization;
using Billiards.Core.Ai;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using Billiards.Core.Table;
using Xunit.Abstractions;

namespace Billiards.Core.Tests.Rules.Games.ThreeCushion;

/// <summary>
/// The diamond aid (F4): its path is the simulated shot's path to the third cushion, and its
/// corner-5 numbers set beside the formula's on the system's standard shots.
/// </summary>
public class DiamondAidTests(ITestOutputHelper output)
{
    private static readonly Scene Scene = SceneLoader.Load(Path.Combine(AssetFolder.Assets, "scenes", "three-cushion.json"));

    /// <summary>The tolerance on a contact's place (m): a tenth of a millimetre.</summary>
    private const double Tolerance = 1e-4;

    public static TheoryData<double, double, double, double> Strokes => new()
    {
        { 3.0, 20, 0.3, 0.1 },
        { 4.5, 35, -0.4, 0 },
        { 3.5, 160, 0.4, 0.2 },
        { 5.0, -30, 0, -0.2 },
        { 2.5, 80, -0.3, 0.3 },
    };

    [Theory]
    [MemberData(nameof(Strokes))]
    public void TheAidsPathIsTheSimulatedShotsPathToTheThirdCushion(double speed, double aimDeg, double side, double height)
    {
        var game = SimulationFactory.Create(Scene);
        var position = TablePosition.Of(game, BallSet.White);
        var shot = new ShotSpec(speed, aimDeg, side, height);
        var aid = DiamondAid.Trace(game.TableModel, position, shot);

        // The shot as the game plays it: struck and run to rest in one go on the scene's simulation.
        var played = SimulationFactory.Create(Scene);
        played.Strike(shot, BallSet.White);
        played.AdvanceTo(60);
        var cushions = played.Events.AsSpan().ToArray().Where(e => e.Kind == EventKind.BallCushion && e.A == BallSet.White).Take(DiamondAid.Cushions).ToList();
        Assert.Equal(DiamondAid.Cushions, cushions.Count);
        Assert.Equal(cushions.Count, aid.Contacts.Count);
        for (int k = 0; k < cushions.Count; k++)
        {
            // The same contact at the same time, where the played ball is at that time.
            Assert.Equal(cushions[k].Time, aid.Contacts[k].Time, 9);
            var probe = SimulationFactory.Create(Scene);
            probe.Strike(shot, BallSet.White);
            probe.AdvanceTo(cushions[k].Time);
            var at = probe.Balls[probe.IndexOf(BallSet.White)].Position;
            Assert.True((at - aid.Contacts[k].Centre).Length < Tolerance, $"contact {k + 1}: {(at - aid.Contacts[k].Centre).Length * 1000:0.000} mm off");
            Assert.Equal(DiamondAid.RailAt(Scene.Table, at), aid.Contacts[k].Rail);
        }
        // The drawn path: the played ball lies on it at every time, and it ends at the third contact.
        Assert.Equal(aid.Contacts[^1].Centre, aid.Path[^1]);
        var check = SimulationFactory.Create(Scene);
        check.Strike(shot, BallSet.White);
        for (int i = 1; i < aid.Path.Count; i += 25)
        {
            double t = Math.Min(i * DiamondAid.SampleSeconds, cushions[^1].Time);
            check.AdvanceTo(t);
            Assert.InRange(DistanceToPath(check.Balls[check.IndexOf(BallSet.White)].Position, aid.Path), 0, Tolerance);
        }
    }

    private static double DistanceToPath(Vec3 p, IReadOnlyList<Vec3> path)
    {
        double best = double.PositiveInfinity;
        for (int i = 0; i + 1 < path.Count; i++)
        {
            var a = path[i];
            var ab = path[i + 1] - a;
            double len2 = Vec3.Dot(ab, ab);
            double f = len2 == 0 ? 0 : Math.Clamp(Vec3.Dot(p - a, ab) / len2, 0, 1);
            best = Math.Min(best, (p - (a + (ab * f))).Length);
        }
        return best;
    }

    /// <summary>
    /// The corner-5 system's standard shots (the far end at the foot, the first rail the left long
    /// rail, running side): the cue ball on the line from origin D through first-rail F, 0.2 m from
    /// D's point, alone on the table, at 3.5 m/s with 0.3 R of running side and a little follow.
    /// The path goes long, foot, long as the system draws it, and its third-rail number is printed
    /// beside the formula's T = D - F (docs/three-cushion.md's table comes from this output).
    /// </summary>
    [Fact]
    public void TheStandardCornerFiveShotsGoLongShortLongAndAreSetBesideTheFormula()
    {
        var model = SimulationFactory.Create(Scene).TableModel;
        var table = Scene.Table;
        double spacing = CaromTable.DiamondSpacing(table), r = BallSet.Carom.Radius;
        var c = CultureInfo.InvariantCulture;
        output.WriteLine("| D | F | formula T = D - F | aid T | rails |");
        output.WriteLine("| --- | --- | --- | --- | --- |");
        foreach (double d in new[] { 5.0, 4.5, 4.0, 3.0, 6.0 })
        {
            foreach (double f in new[] { 1.0, 2.0, 3.0 }.Where(f => d - f >= 1))
            {
                var origin = d <= 5 ? new Vec3(-table.HalfLength + ((5 - d) * 2 * spacing), -table.HalfWidth, r) : new Vec3(-table.HalfLength, -table.HalfWidth + ((d - 5) * spacing), r);
                var aimPoint = new Vec3(table.HalfLength - (f * spacing), table.HalfWidth, r);
                var dir = (aimPoint - origin) * (1 / (aimPoint - origin).Length);
                var cue = origin + (dir * 0.2);
                Assert.InRange(Math.Abs(cue.Y), 0, table.HalfWidth - r);
                Assert.InRange(Math.Abs(cue.X), 0, table.HalfLength - r);
                double aim = DeterministicMath.Atan2(dir.Y, dir.X) * 180 / Math.PI;
                var aid = DiamondAid.Trace(model, new TablePosition([(BallSet.White, cue)], BallSet.White), new ShotSpec(3.5, aim, 0.3, 0.1));
                Assert.Equal(d, aid.Origin!.Value, 6);
                Assert.Equal(f, aid.FirstRail!.Value, 6);
                Assert.Equal([CaromRail.Left, CaromRail.Foot, CaromRail.Right], aid.Contacts.Select(k => k.Rail));
                output.WriteLine(string.Create(c, $"| {d} | {f} | {aid.FormulaThirdRail:0.0} | {aid.ThirdRail:0.00} | {string.Join(", ", aid.Contacts.Select(k => k.Rail))} |"));
            }
        }
    }
}
