using Billiards.Core.Ai;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Ai;

/// <summary>Positions and a shot runner shared by the planner's tests.</summary>
internal static class PlannerKit
{
    public static readonly TableSpec Pool = TableSpec.FromPreset("pool-9ft");
    public static readonly PhysicsParams Params = PhysicsParams.Default;
    public static readonly ShotPlanner Planner = new(Pool, Params);

    /// <summary>
    /// Cue ball, the 1 on the straight line from the cue ball to <paramref name="pocket"/>'s aim
    /// point, <paramref name="toPocket"/> m from it and <paramref name="cueGap"/> m behind it, and the 2
    /// out of the way.
    /// </summary>
    public static TablePosition StraightIn(PocketId pocket, double toPocket, double cueGap, Vec3? far = null)
    {
        var aim = Planner.Table.AimPoint(pocket);
        var dir = (aim - new Vec3(0, 0, aim.Z)).XY.Normalized();
        if (pocket == PoolPockets.SideLeft || pocket == PoolPockets.SideRight)
        {
            dir = new Vec3(0, Math.Sign(aim.Y), 0);
        }
        var o = (aim - dir * toPocket) with { Z = Params.R };
        var cue = (o - dir * cueGap) with { Z = Params.R };
        var other = far ?? new Vec3(-Pool.HalfLength + 0.2, -Math.Sign(o.Y == 0 ? 1 : o.Y) * (Pool.HalfWidth - 0.1), Params.R);
        return new TablePosition([(PoolBalls.Cue, cue), (new BallId(1), o), (new BallId(2), other)], PoolBalls.Cue);
    }

    /// <summary>Simulates a shot from a position; returns the record.</summary>
    public static ShotRecord Simulate(TablePosition position, ShotSpec shot, Vec3? place = null)
    {
        var start = place is { } p ? position.With(PoolBalls.Cue, p) : position;
        var sim = start.CreateSimulation(Pool, Params);
        sim.Strike(shot);
        sim.AdvanceTo(120);
        return ShotRecord.LastShot(sim, shot);
    }
}
