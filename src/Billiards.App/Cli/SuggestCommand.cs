using System.CommandLine;
using System.Text;
using System.Text.Json;
using Billiards.Core.Ai;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Cli;

/// <summary>
/// <c>suggest SCENE [--level 1..5] [--budget-ms MS] [--noise NAME[:K]]</c>: the computer player's choice for the
/// scene's position and game, printed as
/// <c>{"shot": {...}, "place": [x, y] or null, "call": {...}, "expected": {"pot": p, "ruling": ...}, "simulations": n, "ms": t}</c>.
/// </summary>
/// <remarks>
/// The game state is the scene's "game" block: a scene with one and no shot is a position, and a
/// shot in it is ignored (scene-format.md). Without one it comes from the scene's "rules"
/// (8-ball when it has none): a scene with a rack is a break, one without is a position after the
/// break with an open table. The decision is seeded, so the same scene gives the same suggestion.
/// With <c>--noise</c> the planner plays for that execution noise (<see cref="SkillLevel.PlayingFor"/>):
/// its search samples the noise in place of the level's own error.
/// </remarks>
public static class SuggestCommand
{
    /// <summary>The level when none is given.</summary>
    public const int DefaultLevel = 3;

    /// <summary>The largest time cap accepted (ms).</summary>
    public const int MaxBudgetMs = 600_000;

    /// <summary>Builds the verb.</summary>
    public static Command Create(TextWriter stdout)
    {
        var scene = new Argument<string>("scene") { Description = "The scene file (billiards-scene/1 JSON)." };
        var level = new Option<int?>("--level") { Description = "The player's level, 1 (beginner) to 5 (strong professional); default 3." };
        var budget = new Option<int?>("--budget-ms") { Description = "Cap on the decision's wall-clock time (ms); default 3000." };
        var noise = new Option<string?>("--noise") { Description = "NAME[:K]: plan for this execution noise, fastfiz (the computational-pool tournaments') scaled by K (default 1)." };
        var command = new Command("suggest", VerbHelp.Verb("Print the computer player's shot for a scene.", "suggest")) { scene, level, budget, noise };
        command.SetAction(parse =>
        {
            int levelValue = parse.GetValue(level) ?? DefaultLevel;
            if (levelValue < SkillLevel.Min || levelValue > SkillLevel.Max)
            {
                throw new CliException($"--level {levelValue}: expected {SkillLevel.Min} to {SkillLevel.Max}");
            }
            int budgetValue = parse.GetValue(budget) ?? PlannerBudget.DefaultMilliseconds;
            if (budgetValue < 1 || budgetValue > MaxBudgetMs)
            {
                throw new CliException($"--budget-ms {budgetValue}: expected 1 to {MaxBudgetMs}");
            }
            var skill = SkillLevel.Of(levelValue);
            if (parse.GetValue(noise) is { } noiseText)
            {
                skill = skill.PlayingFor(SelfplayCommand.ParseNoise(noiseText));
            }
            var loaded = SceneLoader.Load(parse.GetValue(scene)!);
            var state = StateOf(loaded);
            var ruleset = Ruleset.For(state.Rules);
            if (!ruleset.HasComputerPlayer)
            {
                throw new CliException($"{state.Rules.ToName()}: the computer player does not play it yet");
            }
            var position = new TablePosition(loaded.Balls.Select(b => (b.Id, b.Position with { Z = loaded.BallRadius })), ruleset.CueBall(state));
            if (position.Count < 2 || !position.ObjectBalls.Any())
            {
                throw new SceneException(loaded.Path, "$.balls", "no object ball to play");
            }
            var planner = new ShotPlanner(loaded.Table, loaded.Physics.Params, loaded.Physics.Models);
            var decision = planner.Decide(state, position, skill, new PlannerBudget(budgetValue), 1);
            stdout.WriteLine(Encoding.UTF8.GetString(ToUtf8(decision, ruleset.BallSet)));
            return 0;
        });
        return command;
    }

    /// <summary>The game state of a scene (see the class remarks).</summary>
    public static GameState StateOf(Scene scene)
    {
        ArgumentNullException.ThrowIfNull(scene);
        if (scene.Game is { } game)
        {
            return game;
        }
        if (scene.Rules is { } name && scene.PlayedAs is null)
        {
            throw new SceneException(scene.Path, "$.rules", $"unknown rules \"{name}\"");
        }
        return new GameState(scene.PlayedAs ?? GameRules.EightBall) { Shot = scene.Rack is null ? 1 : 0 };
    }

    /// <summary>The suggestion's JSON.</summary>
    public static byte[] ToUtf8(Decision decision, Core.Balls.BallSet ballSet)
    {
        ArgumentNullException.ThrowIfNull(decision);
        ArgumentNullException.ThrowIfNull(ballSet);
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true }))
        {
            w.WriteStartObject();
            GameRecordFile.WriteShot(w, "shot", decision.Shot);
            GameRecordFile.WritePlace(w, "place", decision.Place);
            if (decision.Call is { } call)
            {
                GameBlockWriter.WriteCall(w, "call", call, ballSet);
            }
            else
            {
                w.WriteNull("call");
            }
            w.WriteStartObject("expected");
            w.WriteNumber("pot", Math.Round(decision.ExpectedPot, 4));
            if (decision.ExpectedRuling is { } ruling)
            {
                w.WritePropertyName("ruling");
                GameBlockWriter.WriteRuling(w, ruling);
            }
            else
            {
                w.WriteNull("ruling");
            }
            w.WriteEndObject();
            w.WriteNumber("simulations", decision.Simulations);
            w.WriteNumber("ms", Math.Round(decision.Milliseconds, 1));
            w.WriteEndObject();
        }
        return stream.ToArray();
    }
}
