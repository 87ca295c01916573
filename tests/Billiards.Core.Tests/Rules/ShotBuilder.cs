using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Rules;

/// <summary>
/// Hand-made shot records: the game's balls resting in a row along y = 0.4 m (far from the
/// kitchen placements the tests use), a cue strike at t = 0, then the events a test names,
/// 0.1 s apart. A pocketed ball is in its pocket after the shot.
/// </summary>
internal sealed class ShotBuilder
{
    public static readonly TableSpec Table = TableSpec.FromPreset("pool-9ft");
    public const double R = PhysicsParams.DefaultRadius;

    private readonly List<BallId> _ids;
    private readonly BallState[] _balls;
    private readonly List<SimEvent> _events = [];

    private ShotBuilder(IReadOnlyList<BallId> ids)
    {
        _ids = [.. ids];
        _balls = new BallState[ids.Count];
        for (int i = 0; i < _balls.Length; i++)
        {
            _balls[i] = new BallState { Position = new Vec3(-1.0 + 0.12 * i, 0.4, R), Pocket = -1, State = MotionState.Stationary };
        }
        _events.Add(new SimEvent(0, EventKind.CueStrike, PoolBalls.Cue, PoolBalls.Cue, -1, 3.0));
    }

    /// <summary>A shot of <paramref name="rules"/> with all its balls on the table.</summary>
    public static ShotBuilder Of(GameRules rules) => new(Referee.BallsOf(rules));

    private double Next => _events.Count * 0.1;

    /// <summary>The cue ball hits <paramref name="ball"/>.</summary>
    public ShotBuilder Hit(int ball) => Collide(0, ball);

    /// <summary>Two balls collide.</summary>
    public ShotBuilder Collide(int a, int b)
    {
        _events.Add(new SimEvent(Next, EventKind.BallBall, new BallId(a), new BallId(b), -1, 1.0));
        return this;
    }

    /// <summary>Balls touch a cushion (the foot rail).</summary>
    public ShotBuilder Rail(params int[] balls)
    {
        foreach (int b in balls)
        {
            _events.Add(new SimEvent(Next, EventKind.BallCushion, new BallId(b), new BallId(b), 0, 0.5));
        }
        return this;
    }

    /// <summary>A ball drops into a pocket (0 = the cue ball).</summary>
    public ShotBuilder Pocket(int ball, PocketId pocket)
    {
        _events.Add(new SimEvent(Next, EventKind.BallPocket, new BallId(ball), new BallId(ball), pocket.Index, 0.8));
        ref var b = ref _balls[_ids.IndexOf(new BallId(ball))];
        b.State = MotionState.Pocketed;
        b.Pocket = pocket.Index;
        return this;
    }

    /// <summary>A ball leaves the table over a rail (0 = the cue ball).</summary>
    public ShotBuilder Jump(int ball)
    {
        _events.Add(new SimEvent(Next, EventKind.BallOffTable, new BallId(ball), new BallId(ball), -1, 2.0));
        _balls[_ids.IndexOf(new BallId(ball))].State = MotionState.OffTable;
        return this;
    }

    /// <summary>Balls that were pocketed before this shot.</summary>
    public ShotBuilder Off(params int[] balls)
    {
        foreach (int n in balls)
        {
            ref var b = ref _balls[_ids.IndexOf(new BallId(n))];
            b.State = MotionState.Pocketed;
            b.Pocket = PoolPockets.FootLeft.Index;
        }
        return this;
    }

    /// <summary>Every object ball but <paramref name="keep"/> was pocketed before this shot.</summary>
    public ShotBuilder OffAllBut(params int[] keep) =>
        Off([.. _ids.Where(id => !PoolBalls.IsCue(id) && !keep.Contains(id.Value)).Select(id => id.Value)]);

    /// <summary>Moves a resting ball (to test placements against it).</summary>
    public ShotBuilder At(int ball, double x, double y)
    {
        _balls[_ids.IndexOf(new BallId(ball))].Position = new Vec3(x, y, R);
        return this;
    }

    public ShotRecord Record() => ShotRecord.Of(_events.ToArray(), _ids, _balls);
}

/// <summary>Shorthands for the tests.</summary>
internal static class RulesKit
{
    public static readonly BallId Cue = PoolBalls.Cue;

    public static BallId B(int n) => new(n);

    public static IReferee RefereeOf(GameRules rules) => Referee.For(rules, ShotBuilder.Table, ShotBuilder.R);

    public static Ruling Judge(GameState before, ShotBuilder shot) => RefereeOf(before.Rules).Judge(before, shot.Record());

    public static GameState Start(GameRules rules) => new(rules) { Players = new("Anna", "Ben") };

    /// <summary>A state after the break, at shot <paramref name="shot"/>, with <paramref name="shooter"/> at the table.</summary>
    public static GameState At(GameRules rules, int shot, int shooter = 0) => Start(rules) with { Shot = shot, Shooter = shooter };

    public static Call Calls(int ball, PocketId pocket) => new(new BallId(ball), pocket);

    public static BallId[] Ids(params int[] n) => [.. n.Select(x => new BallId(x))];

    /// <summary>Asserts the parts of a ruling every rule decides.</summary>
    public static void Expect(Ruling r, Foul[] fouls, bool cont, BallInHand hand, int nextShooter, bool gameOver = false, int? winner = null)
    {
        Assert.Equal(fouls, r.Fouls);
        Assert.Equal(fouls.Length == 0, r.Legal);
        Assert.Equal(cont, r.Continue);
        Assert.Equal(hand, r.BallInHand);
        Assert.Equal(gameOver, r.GameOver);
        Assert.Equal(winner, r.Winner);
        Assert.Equal(nextShooter, r.Next.Shooter);
        Assert.False(string.IsNullOrWhiteSpace(r.Message));
    }
}
