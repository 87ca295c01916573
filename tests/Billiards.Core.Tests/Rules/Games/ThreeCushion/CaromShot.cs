using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Rules.Games.ThreeCushion;

/// <summary>
/// Hand-made three-cushion shot records: the white, the yellow and the red resting apart on the
/// carom table, a strike of the named cue ball at t = 0, then the events a test names, 0.1 s apart.
/// </summary>
internal sealed class CaromShot
{
    public static readonly TableSpec Table = TableSpec.FromPreset(CaromTable.Preset);
    public static readonly double R = BallSet.Carom.Radius;
    public static readonly BallId W = BallSet.White, Y = BallSet.Yellow, Red = BallSet.Red;

    private static readonly BallId[] Ids = [W, Y, Red];
    private readonly BallState[] _balls = new BallState[3];
    private readonly List<SimEvent> _events = [];

    private CaromShot(BallId struck)
    {
        for (int i = 0; i < 3; i++)
        {
            _balls[i] = new BallState { Position = new Vec3(-0.6 + 0.4 * i, 0.3, R), Pocket = -1, State = MotionState.Stationary };
        }
        _events.Add(new SimEvent(0, EventKind.CueStrike, struck, struck, -1, 3.0));
    }

    /// <summary>A shot that strikes <paramref name="struck"/>.</summary>
    public static CaromShot Striking(BallId struck) => new(struck);

    private double Next => _events.Count * 0.1;

    /// <summary>Ball <paramref name="a"/> meets ball <paramref name="b"/>.</summary>
    public CaromShot Hit(BallId a, BallId b)
    {
        _events.Add(new SimEvent(Next, EventKind.BallBall, a, b, -1, 1.0));
        return this;
    }

    /// <summary><paramref name="ball"/> meets <paramref name="count"/> cushions, one after the other.</summary>
    public CaromShot Cushions(BallId ball, int count)
    {
        for (int k = 0; k < count; k++)
        {
            _events.Add(new SimEvent(Next, EventKind.BallCushion, ball, ball, k % 4, 0.5));
        }
        return this;
    }

    /// <summary><paramref name="ball"/> leaves the table.</summary>
    public CaromShot OffTable(BallId ball)
    {
        _events.Add(new SimEvent(Next, EventKind.BallOffTable, ball, ball, -1, 2.0));
        _balls[Array.IndexOf(Ids, ball)].State = MotionState.OffTable;
        return this;
    }

    /// <summary><paramref name="ball"/> comes to rest at <paramref name="x"/>, <paramref name="y"/>.</summary>
    public CaromShot Rests(BallId ball, double x, double y)
    {
        _balls[Array.IndexOf(Ids, ball)].Position = new Vec3(x, y, R);
        return this;
    }

    public ShotRecord Build() => ShotRecord.Of([.. _events], Ids, _balls);
}
