using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Rules.Games;

/// <summary>
/// Hand-made snooker shots: the balls of the rack (seed 1, the cue ball in the D) as they stand
/// before the shot, a cue strike at t = 0 aimed along <see cref="ShotSpec.AimDeg"/>, then the
/// events a test names 0.1 s apart; the balls after are those before, moved and pocketed as told.
/// </summary>
internal sealed class SnookerShot
{
    public static readonly TableSpec Table = TableSpec.FromPreset("snooker-12ft");
    public const double R = 0.02625;

    private static readonly BallId Cue = BallSet.Snooker.CueBalls[0];

    private readonly List<BallId> _ids = [.. BallSet.Snooker.Ids];
    private readonly BallState[] _before;
    private readonly BallState[] _after;
    private readonly List<SimEvent> _events = [];
    private double _aim;

    public SnookerShot()
    {
        var rack = Initializer.Rack(new RackSpec(RackGame.Snooker, 1), Table, R).ToDictionary(b => b.Id, b => b.Position);
        _before = [.. _ids.Select(id => new BallState { Position = rack[id], Pocket = -1, State = MotionState.Stationary })];
        _after = [.. _before];
        _events.Add(new SimEvent(0, EventKind.CueStrike, Cue, Cue, -1, 3.0));
    }

    public static BallId Id(string name) => BallSet.Snooker.TryParse(name, out var id) ? id : throw new ArgumentException(name);

    private int Index(string name) => _ids.IndexOf(Id(name));

    private double Next => _events.Count * 0.1;

    /// <summary>The cue ball first (or next) hits <paramref name="ball"/>.</summary>
    public SnookerShot Hit(string ball) => Collide("cue", ball);

    public SnookerShot Collide(string a, string b)
    {
        _events.Add(new SimEvent(Next, EventKind.BallBall, Id(a), Id(b), -1, 1.0));
        return this;
    }

    /// <summary>A ball drops into a pocket during the shot.</summary>
    public SnookerShot Pot(string ball, int pocket = 4)
    {
        _events.Add(new SimEvent(Next, EventKind.BallPocket, Id(ball), Id(ball), pocket, 0.8));
        ref var b = ref _after[Index(ball)];
        b.State = MotionState.Pocketed;
        b.Pocket = pocket;
        return this;
    }

    /// <summary>A ball leaves the table over a rail.</summary>
    public SnookerShot OffTable(string ball)
    {
        _events.Add(new SimEvent(Next, EventKind.BallOffTable, Id(ball), Id(ball), -1, 2.0));
        _after[Index(ball)].State = MotionState.OffTable;
        return this;
    }

    /// <summary>The cue ball leaves the bed.</summary>
    public SnookerShot Airborne()
    {
        _events.Add(new SimEvent(Next, EventKind.BallAirborne, Cue, Cue, -1, 1.0));
        return this;
    }

    /// <summary>Balls off the table before the shot (pocketed earlier in the frame).</summary>
    public SnookerShot Gone(params string[] balls)
    {
        foreach (string n in balls)
        {
            _before[Index(n)].State = _after[Index(n)].State = MotionState.Pocketed;
        }
        return this;
    }

    /// <summary>Every red is gone, and every colour but <paramref name="keep"/>.</summary>
    public SnookerShot Only(params string[] keep) =>
        Gone([.. BallSet.Snooker.Balls.Where(b => b.Name != "cue" && !keep.Contains(b.Name)).Select(b => b.Name)]);

    /// <summary>Stands a ball at (x, y) before and after the shot.</summary>
    public SnookerShot At(string ball, double x, double y)
    {
        _before[Index(ball)].Position = _after[Index(ball)].Position = new Vec3(x, y, R);
        return this;
    }

    /// <summary>Where a ball comes to rest after the shot.</summary>
    public SnookerShot Rests(string ball, double x, double y)
    {
        _after[Index(ball)].Position = new Vec3(x, y, R);
        return this;
    }

    public SnookerShot Aim(double degrees)
    {
        _aim = degrees;
        return this;
    }

    public ShotRecord Record() => ShotRecord.Of(_events.ToArray(), _ids, _after, new ShotSpec(3.0, _aim), _before);

    public static IReferee Referee => Ruleset.For(GameRules.Snooker).Referee(Table, R);

    public Ruling Judge(GameState before) => Referee.Judge(before, Record());

    public static GameState Frame => new(GameRules.Snooker) { Players = new("Anna", "Ben"), Shot = 5 };
}
