using BenchmarkDotNet.Configs;
using BenchmarkDotNet.Jobs;
using BenchmarkDotNet.Toolchains.DotNetCli;
using Billiards.Core.Ai;
using Billiards.Core.Physics.Standard;
using Billiards.Core.Rules;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Benchmarks;

/// <summary>
/// The level-5 decision of <c>AiBenchmarks</c> (the open 8-ball table after the seeded break) on one
/// core, for several builds of this project side by side in one run: against today's Billiards.Core
/// (job <c>today</c>) and against older Cores that <c>BILLIARDS_BASELINE_CORE</c> names
/// (<c>tools/bench/turn-controller.sh</c>: the Core the turn controller was built on, 03cad24, and
/// the turn controller's own branch before the other work merged, c4c8cca).
/// Both builds play the same physics (the tip on the ball's face, as the old Core struck), so the
/// returned expected score shows whether they made the same decision.
/// </summary>
/// <remarks>
/// This file compiles against both Cores (<c>CORE_BASELINE</c> marks the old one's calls); in the
/// baseline build it is the project's only benchmark.
/// </remarks>
[Config(typeof(TurnControllerConfig))]
public class TurnControllerBenchmarks
{
    private ShotPlanner _planner = null!;
    private TablePosition _open = null!;
    private GameState _state = null!;

    [GlobalSetup]
    public void Setup()
    {
        var table = TableSpec.FromPreset("pool-9ft");
#if CORE_BASELINE
        var physics = PhysicsParams.Default;
#else
        var physics = PhysicsParams.Default with { Tip = TipFrame.Face };
#endif
        var cue = Core.Balls.BallSet.Pool.CueBalls[0];
        var rack = TablePosition.Rack(new RackSpec(RackGame.EightBall, 5), table, physics.R, cue);
        _planner = new ShotPlanner(table, physics);
        var sim = rack.CreateSimulation(table, physics);
        sim.Strike(new ShotSpec(7, 0.3, 0, -0.2));
        sim.AdvanceTo(120);
        _open = TablePosition.Of(sim, cue);
        _state = new GameState(GameRules.EightBall) { Shot = 1, BallInHand = _open.Cue is null ? BallInHand.Table : BallInHand.None };
    }

    /// <summary>One level-5 decision on one core; returns its expected score.</summary>
    [Benchmark]
    public double Decide() => _planner.Decide(_state, _open, SkillLevel.Of(5), new PlannerBudget(60_000, 1), 1).ExpectedScore;

    /// <summary>
    /// Today's build, and one build per older Core that <c>BILLIARDS_BASELINE_CORE</c> names
    /// (<c>id=path-of-its-DLL</c> entries separated by <c>;</c>, the job named by its id).
    /// </summary>
    private sealed class TurnControllerConfig : ManualConfig
    {
        public TurnControllerConfig()
        {
            if (Environment.GetEnvironmentVariable("BILLIARDS_BASELINE_CORE") is not { Length: > 0 } baselines)
            {
                return; // the command line's job (CI's dry smoke run)
            }
            var job = Job.ShortRun.WithIterationCount(15);
            AddJob(job.WithId("today").AsBaseline());
            foreach (var entry in baselines.Split(';', StringSplitOptions.RemoveEmptyEntries))
            {
                var (id, dll) = entry.Split('=', 2) is [var name, var path] ? (name, path) : throw new ArgumentException($"BILLIARDS_BASELINE_CORE: '{entry}' is not id=path");
                AddJob(job.WithArguments([new MsBuildArgument($"/p:CoreBaseline={dll}")]).WithId(id));
            }
        }
    }
}
