using System.Reflection;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Physics;

/// <summary>
/// The debug-build state checker (<see cref="StateChecker"/>): a ball off the table, an overlap and
/// a non-finite value are caught.
/// </summary>
public class StateCheckerTests
{
    private static void CheckByReflection(Simulation sim, double radius, bool overlap)
    {
        // The checker is [Conditional("DEBUG")]: called directly from a Release build it would vanish.
        var method = typeof(StateChecker).GetMethod(nameof(StateChecker.Check), BindingFlags.Public | BindingFlags.Static)!;
        try
        {
            method.Invoke(null, [sim, radius, overlap]);
        }
        catch (TargetInvocationException e) when (e.InnerException is not null)
        {
            throw e.InnerException;
        }
    }

    [Fact]
    public void TheDebugCheckerFindsABallOffTheTableAnOverlapAndANaN()
    {
        var table = TableSpec.FromPreset("pool-9ft");
        double r = PhysicsParams.DefaultRadius;
        Simulation Make(params Vec3[] positions) => SimulationFactory.Create(new Scene("check", null, table, PhysicsConfig.Default, null,
            [.. positions.Select((p, i) => new BallSetup(new BallId(i), p with { Z = r }, Vec3.Zero, Vec3.Zero))], null, null));

        CheckByReflection(Make(new Vec3(0, 0, 0), new Vec3(0.1, 0, 0)), r, overlap: true);
        var off = Assert.Throws<InvalidOperationException>(() => CheckByReflection(Make(new Vec3(5, 0, 0)), r, overlap: true));
        Assert.Contains("left the table", off.Message, StringComparison.Ordinal);
        var overlap = Assert.Throws<InvalidOperationException>(() => CheckByReflection(Make(new Vec3(0, 0, 0), new Vec3(0.05, 0, 0)), r, overlap: true));
        Assert.Contains("overlap", overlap.Message, StringComparison.Ordinal);
        CheckByReflection(Make(new Vec3(0, 0, 0), new Vec3(0.05, 0, 0)), r, overlap: false);
        var nan = Assert.Throws<InvalidOperationException>(() => CheckByReflection(Make(new Vec3(double.NaN, 0, 0)), r, overlap: true));
        Assert.Contains("non-finite", nan.Message, StringComparison.Ordinal);
    }

    /// <summary>
    /// The table-bound guarantee at rest: a ball on the bed is on the bed, one half a radius into
    /// the foot cushion is inside it, one in the foot-left pocket's mouth is on the bed, and ones at
    /// the bed's height over the rail or the floor (which no physics puts there) are outside.
    /// </summary>
    [Fact]
    public void PlaceOfTellsTheBedACushionAMouthAndOutsideApart()
    {
        var table = TableSpec.FromPreset("pool-9ft");
        double r = PhysicsParams.DefaultRadius;
        var mouth = table.Pockets[4].MouthMiddle(table);
        Vec3[] positions = [new(0.3, -0.2, r), new(table.HalfLength - r / 2, 0, r), mouth with { Z = r }, new(table.HalfLength + 0.05, 0, r), new(5, 0, r)];
        var sim = SimulationFactory.Create(new Scene("place", null, table, PhysicsConfig.Default, null,
            [.. positions.Select((p, i) => new BallSetup(new BallId(i), p, Vec3.Zero, Vec3.Zero))], null, null));
        Assert.Equal(
            [BallPlace.Bed, BallPlace.InsideCushion, BallPlace.Bed, BallPlace.Outside, BallPlace.Outside],
            Enumerable.Range(0, positions.Length).Select(i => StateChecker.PlaceOf(sim, i)));
    }
}
