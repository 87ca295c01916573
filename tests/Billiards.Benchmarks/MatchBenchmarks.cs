using Billiards.Core.Ai;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.Benchmarks;

/// <summary>
/// The match: one judged shot (the 8-ball break from the rack, struck, run to rest with the
/// planner's event integrator, judged and applied: what self-play pays once a shot, and paid twice
/// before the match judged each shot once), and one whole self-play game of 9-ball at levels 1 and 1.
/// </summary>
public class MatchBenchmarks
{
    private static readonly TableSpec Table = TableSpec.FromPreset("pool-9ft");
    private GameSetup _setup = null!;
    private GameShot _break = null!;
    private SelfPlay _selfPlay = null!;

    [GlobalSetup]
    public void Setup()
    {
        _selfPlay = new SelfPlay(Table, PhysicsParams.Default);
        _setup = new GameSetup(Table, _selfPlay.Planner.PhysicsConfig, 5, new GameState(GameRules.EightBall));
        var head = Core.Setup.Initializer.HeadSpot(Table, _setup.BallRadius);
        _break = new GameShot(new ShotSpec(8, 0.2, 0, -0.2), null, head);
    }

    /// <summary>One judged shot: a match racked, its break struck, run to rest, judged and applied.</summary>
    [Benchmark]
    public int PlayBreak() => new Match(_setup).Play(_break).Ruling.Pocketed.Count;

    /// <summary>One whole self-play game of 9-ball, levels 1 and 1, a fixed seed (the planner's search on both cores).</summary>
    [Benchmark]
    public int SelfPlayNineBallGame() => _selfPlay.Play(GameRules.NineBall, new PerPlayer<int>(1, 1), 0, 41, new PlannerBudget(60_000)).Shots.Count;
}
