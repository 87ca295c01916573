using System.Text.Json;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.App.Tests.Rules.Pocketless;

/// <summary>
/// A test-only game on the pocketless table, registered by name from here alone (no file of Core
/// or the App names it): "touch", the cue ball and the 1. A shot whose cue ball meets the 1 scores
/// a point and the shooter plays on; one that misses it hands the table over. The first to
/// <see cref="Points"/> wins. Its rack (the 1 on the foot spot) and cue start (the head spot) are
/// its own, and so are its part of the game state (<see cref="TouchPart"/>: the misses of the
/// whole game) and the game-block field that carries it ("touch_misses").
/// </summary>
internal sealed class TouchRuleset : Ruleset
{
    /// <summary>The points that win.</summary>
    public const int Points = 3;

    /// <summary>The game.</summary>
    public static GameRules Touch { get; } = new("touch");

    private static readonly BallId One = new(1);

    /// <summary>Registers the game (once; again does nothing).</summary>
    public static GameRules Register()
    {
        Ruleset.Register(new TouchRuleset());
        return Touch;
    }

    public override GameRules Game => Touch;

    public override string ShortName => "touch";

    public override string TablePreset => "pocketless";

    public override IReadOnlyList<BallId> Balls => [BallSet.CueBalls[0], One];

    public override BallInHand BreakBallInHand => BallInHand.None;

    public override bool CallsShots => false;

    public override bool HasThreeFouls => false;

    public override bool PowerBreak => false;

    public override int MaxShots(GameState start) => 60;

    public override IReadOnlyList<(BallId Id, Vec3 Position)> Rack(TableSpec table, double ballRadius, int seed) =>
        [(One, new Vec3(table.Length / 4, 0, ballRadius))];

    public override Vec3 CueStart(TableSpec table, double ballRadius) => new(-table.Length / 4, 0, ballRadius);

    public override IReferee Referee(TableSpec table, double ballRadius) => new TouchReferee(table, ballRadius);

    public override GameStatePart? StartPart { get; } = new TouchPart();

    public override IReadOnlyList<string> PartFields { get; } = [TouchPart.Field];

    public override GameStatePart? ReadPart(GameBlockFields block) =>
        block.TryGet(TouchPart.Field, out var misses) ? new TouchPart { Misses = block.Pair(TouchPart.Field, misses) } : StartPart;

    public override void WritePart(Utf8JsonWriter writer, GameState state, GameBlockSlot slot)
    {
        if (slot == GameBlockSlot.AtEnd)
        {
            GameBlockWriter.WritePair(writer, TouchPart.Field, state.PartOf<TouchPart>().Misses);
        }
    }

    public override IReadOnlyList<BallId> LegalTargets(GameState state, IEnumerable<BallId> objectBalls) => [.. objectBalls.Where(b => b == One)];

    public override HudTarget Target(GameState state, int player, IReadOnlyCollection<BallId> objectBalls) =>
        new($"{state.Score[player]} of {Points}", [One]);

    private sealed class TouchReferee(TableSpec table, double ballRadius) : IReferee
    {
        public GameRules Rules => Touch;

        public TableSpec Table { get; } = table;

        public double BallRadius { get; } = ballRadius;

        public Ruling Judge(GameState before, ShotRecord shot)
        {
            bool hit = shot.FirstContact == One;
            int shooter = before.Shooter;
            var misses = before.PartOf<TouchPart>().Misses;
            var score = hit ? before.Score.With(shooter, before.Score[shooter] + 1) : before.Score;
            bool won = score[shooter] >= Points;
            string message = won ? $"{before.ShooterName} touches the 1 and wins."
                : hit ? $"{before.ShooterName} touches the 1: {score[shooter]} points."
                : $"{before.ShooterName} misses the 1: {before.Players[before.Incoming]} is at the table.";
            var next = won
                ? new GameState(Touch) { Players = before.Players, Shooter = shooter, Target = before.Target }
                : before with
                {
                    Shooter = hit ? shooter : before.Incoming, Shot = before.Shot + 1, Score = score, Call = null, PushOut = false, Placement = null, BallInHand = BallInHand.None,
                    Part = new TouchPart { Misses = hit ? misses : misses.With(shooter, misses[shooter] + 1) },
                };
            return new Ruling(true, [], [], hit && !won, BallInHand.None, [], [], won, won ? shooter : null, message, next) { Score = score };
        }
    }
}

/// <summary>Touch's own part of the game state: each player's misses of the 1 in the game.</summary>
internal sealed record TouchPart : GameStatePart
{
    /// <summary>The game-block field that carries it.</summary>
    public const string Field = "touch_misses";

    /// <summary>Each player's misses.</summary>
    public PerPlayer<int> Misses { get; init; }
}

/// <summary>Touch without a computer player: the window seats people only.</summary>
internal sealed class TouchByHandRuleset : Ruleset
{
    private readonly TouchRuleset _touch = new();

    /// <summary>The game.</summary>
    public static GameRules TouchByHand { get; } = new("touch-by-hand");

    /// <summary>Registers the game (once; again does nothing).</summary>
    public static GameRules Register()
    {
        Ruleset.Register(new TouchByHandRuleset());
        return TouchByHand;
    }

    public override GameRules Game => TouchByHand;

    public override string ShortName => "touch by hand";

    public override bool HasComputerPlayer => false;

    public override string TablePreset => _touch.TablePreset;

    public override IReadOnlyList<BallId> Balls => _touch.Balls;

    public override IReadOnlyList<(BallId Id, Vec3 Position)> Rack(TableSpec table, double ballRadius, int seed) => _touch.Rack(table, ballRadius, seed);

    public override Vec3 CueStart(TableSpec table, double ballRadius) => _touch.CueStart(table, ballRadius);

    public override IReferee Referee(TableSpec table, double ballRadius) => _touch.Referee(table, ballRadius);

    public override IReadOnlyList<BallId> LegalTargets(GameState state, IEnumerable<BallId> objectBalls) => _touch.LegalTargets(state, objectBalls);

    public override HudTarget Target(GameState state, int player, IReadOnlyCollection<BallId> objectBalls) => _touch.Target(state, player, objectBalls);
}
