using System.Globalization;
using Billiards.App.Game;
using Billiards.Core.Balls;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.App.Hud;

/// <summary>One player on the scoreboard.</summary>
/// <param name="Name">The name, with "(computer)" for the computer.</param>
/// <param name="AtTable">True for the shooter (the game on).</param>
/// <param name="Target">A few words on what the player needs ("solids", "on the 4", "open table").</param>
/// <param name="Balls">The balls the player still needs, drawn as big icons (numbers).</param>
/// <param name="Detail">The score (14.1) and the fouls in a row where a third foul matters, or empty.</param>
public sealed record PlayerCard(string Name, bool AtTable, string Target, IReadOnlyList<int> Balls, string Detail);

/// <summary>The match's scoreboard along the top edge.</summary>
/// <param name="Title">The game, the shot and the games won.</param>
/// <param name="Corner">Short keys and states at the title's far end: help, developer lines, sound.</param>
/// <param name="Players">The two players.</param>
/// <param name="Status">Who acts now and how: the player's keys on their turn, the computer's state on its own.</param>
/// <param name="Message">The last message (a ruling, a hint, a new game), kept until the next shot; wrapped to fit.</param>
/// <param name="Log">The game's earlier rulings, newest first (a short log).</param>
public sealed record Scoreboard(string Title, string Corner, IReadOnlyList<PlayerCard> Players, string Status, string? Message, IReadOnlyList<string> Log);

/// <summary>The cue's settings drawn as diagrams: the tip on the cue ball, the cue's elevation, the power.</summary>
/// <param name="Spin">The tip's offset [side, height] as fractions of R.</param>
/// <param name="ElevationDegrees">The cue's elevation as struck (deg), raised over a rail or a ball.</param>
/// <param name="Power">The keyboard power as a share of the strongest, 0..1, or null without one (free play strikes with the mouse).</param>
public sealed record CueGauges(System.Numerics.Vector2 Spin, float ElevationDegrees, float? Power);

/// <summary>A player's game in numbers, for the result panel.</summary>
/// <param name="Shots">Shots struck.</param>
/// <param name="Pots">Object balls pocketed on legal shots.</param>
/// <param name="Fouls">Fouls committed.</param>
/// <param name="HighestBreak">The best of the player's visits to the table by the ruleset's break (<see cref="Ruleset.Visits"/>): pool's balls that stayed down, snooker's points.</param>
public readonly record struct PlayerStats(int Shots, int Pots, int Fouls, int HighestBreak)
{
    /// <summary>The sum of the player's visits' breaks (three-cushion's points).</summary>
    public int BreakSum { get; init; }

    /// <summary>The player's visits to the table (three-cushion's innings).</summary>
    public int Visits { get; init; }

    /// <summary>Each player's numbers from a game's shots under <paramref name="ruleset"/>.</summary>
    public static PerPlayer<PlayerStats> Of(Ruleset ruleset, IReadOnlyList<MatchShot> shots)
    {
        ArgumentNullException.ThrowIfNull(ruleset);
        ArgumentNullException.ThrowIfNull(shots);
        var stats = new PlayerStats[2];
        foreach (var shot in shots)
        {
            int p = shot.Before.Shooter;
            var s = stats[p];
            stats[p] = s with { Shots = s.Shots + 1, Pots = s.Pots + (shot.Ruling.Legal ? shot.Ruling.Pocketed.Count : 0), Fouls = s.Fouls + (shot.Ruling.Legal ? 0 : 1) };
        }
        foreach (var visit in ruleset.Visits(shots.Select(s => (s.Before.Shooter, s.Ruling))))
        {
            var v = stats[visit.Player];
            stats[visit.Player] = v with { HighestBreak = Math.Max(v.HighestBreak, visit.Break), BreakSum = v.BreakSum + visit.Break, Visits = v.Visits + 1 };
        }
        return new PerPlayer<PlayerStats>(stats[0], stats[1]);
    }
}

/// <summary>The result panel at game over: who won, and each player's game in numbers.</summary>
/// <param name="Title">"Anna wins" (or how the game ended without a winner).</param>
/// <param name="Names">The players' names.</param>
/// <param name="Stats">Their numbers.</param>
/// <param name="Games">The games each has won in the match.</param>
public sealed record ResultPanel(string Title, PerPlayer<string> Names, PerPlayer<PlayerStats> Stats, PerPlayer<int> Games)
{
    /// <summary>The ruleset's word for a visit's score (<see cref="Ruleset.BreakWord"/>): "run", snooker's "break".</summary>
    public string BreakWord { get; init; } = "run";

    /// <summary>The ruleset's word for a game (<see cref="Ruleset.GameWord"/>): "game", snooker's "frame".</summary>
    public string GameWord { get; init; } = "game";

    /// <summary>Three-cushion's score sheet (<see cref="Ruleset.HasInnings"/>): points, innings, the average and the highest run instead of pots and fouls.</summary>
    public bool ScoreSheet { get; init; }

    /// <summary>The panel's rows: a label and each player's figure.</summary>
    public IReadOnlyList<(string Label, string First, string Second)> Rows => ScoreSheet ?
    [
        ("Points", Text(Stats.First.BreakSum), Text(Stats.Second.BreakSum)),
        ("Innings", Text(Stats.First.Visits), Text(Stats.Second.Visits)),
        ("Average", ThreeCushionRuleset.Average(Stats.First.BreakSum, Stats.First.Visits), ThreeCushionRuleset.Average(Stats.Second.BreakSum, Stats.Second.Visits)),
        ($"Highest {BreakWord}", Text(Stats.First.HighestBreak), Text(Stats.Second.HighestBreak)),
        ($"{ScoreboardBuilder.Capitalised(GameWord)}s won", Text(Games.First), Text(Games.Second)),
    ] :
    [
        ("Shots", Text(Stats.First.Shots), Text(Stats.Second.Shots)),
        ("Pots", Text(Stats.First.Pots), Text(Stats.Second.Pots)),
        ("Fouls", Text(Stats.First.Fouls), Text(Stats.Second.Fouls)),
        ($"Highest {BreakWord}", Text(Stats.First.HighestBreak), Text(Stats.Second.HighestBreak)),
        ($"{ScoreboardBuilder.Capitalised(GameWord)}s won", Text(Games.First), Text(Games.Second)),
    ];

    private static string Text(int n) => n.ToString(CultureInfo.InvariantCulture);
}

/// <summary>Builds the scoreboard and the result panel from the match; it only reads.</summary>
public static class ScoreboardBuilder
{
    /// <summary>The earlier rulings the log shows at most.</summary>
    public const int LogLength = 2;

    /// <summary>The scoreboard of <paramref name="match"/> now.</summary>
    /// <param name="match">The match.</param>
    /// <param name="physics">The table (its balls).</param>
    /// <param name="computerStatus">What the computer (or the hint's search) does now, or null.</param>
    /// <param name="paused">True while the game is paused.</param>
    /// <param name="sound">The sound's state line, or null.</param>
    public static Scoreboard Of(MatchNode match, PhysicsNode physics, string? computerStatus, bool paused, string? sound)
    {
        ArgumentNullException.ThrowIfNull(match);
        ArgumentNullException.ThrowIfNull(physics);
        var state = match.Session.State;
        var onTable = physics.ObjectBallsOnTable();
        var shots = match.Session.Game?.Shots ?? [];
        var fouls = FoulsInRow(match, shots);
        var cards = new PlayerCard[2];
        var ruleset = match.Session.Ruleset;
        int? remaining = ruleset.PointsRemaining(state, onTable);
        for (int p = 0; p < 2; p++)
        {
            var target = ruleset.Target(state, p, onTable);
            if (p == state.Shooter && match.Call.CurrentNomination is { } nominated)
            {
                // The colour or the free ball nominated now, before the strike makes it the state's call.
                string ballName = BallSet.NameOfAny(nominated.Ball);
                target = SnookerPart.Of(state).FreeBall
                    ? target with { Text = string.Create(CultureInfo.InvariantCulture, $"{state.Score[p]}, free ball: {ballName}") }
                    : ruleset.Target(state with { Call = nominated }, p, onTable);
            }
            var detail = new List<string>();
            // A game with a ball on (snooker) has the score in the target's words; 14.1 beside them.
            if (ruleset.HasScore && !ruleset.HasBallOn)
            {
                detail.Add(string.Create(CultureInfo.InvariantCulture, $"score {state.Score[p]} of {state.Target}"));
            }
            if (ruleset.HasScore && p == state.Shooter && !match.Session.IsOver)
            {
                detail.Add(string.Create(CultureInfo.InvariantCulture, $"{ruleset.BreakWord} {CurrentBreak(ruleset, shots, p)}"));
            }
            if (!match.Session.IsOver && ruleset.NeedsSnookers(state, p, onTable))
            {
                detail.Add("needs snookers");
            }
            // Only where a third foul in a row costs something (not 8-ball).
            if (ruleset.HasThreeFouls && fouls[p] > 0)
            {
                detail.Add(string.Create(CultureInfo.InvariantCulture, $"fouls in a row {fouls[p]}"));
            }
            string name = match.Session.Seats[p].IsHuman || state.Players[p].StartsWith("Computer", StringComparison.Ordinal) ? state.Players[p] : $"{state.Players[p]} (computer)";
            if (ruleset.HasBallOn && match.Session.IsOver)
            {
                // The game is over: the final score, no ball on.
                target = new HudTarget(string.Create(CultureInfo.InvariantCulture, $"{state.Score[p]}"), []);
            }
            cards[p] = new PlayerCard(name, p == state.Shooter && !match.Session.IsOver, target.Text, [.. target.Balls.Select(b => b.Value)], string.Join("  ", detail));
        }
        string points = remaining is int r ? string.Create(CultureInfo.InvariantCulture, $"  remaining {r}") : "";
        string title = $"{GameName(state.Rules)}  shot {state.Shot}{points}  {ruleset.GameWord}s {match.Session.GamesWon.First}-{match.Session.GamesWon.Second}{(paused ? "  PAUSED (P)" : "")}";
        string corner = sound is null ? "H help" : $"H help  {SoundWord(sound)}";
        var rulings = shots.Select(s => s.Ruling.Message).Reverse().Where(m => m != match.Session.Message).Take(LogLength).ToList();
        return new Scoreboard(title, corner, cards, Status(match, physics, computerStatus), match.Session.Message, rulings);
    }

    /// <summary>The result panel, or null while the game is on.</summary>
    public static ResultPanel? Result(MatchNode match)
    {
        ArgumentNullException.ThrowIfNull(match);
        if (!match.Session.IsOver || match.Session.Game is not { } game)
        {
            return null;
        }
        var names = match.Session.State.Players;
        var score = match.Session.State.Score;
        var ruleset = match.Session.Ruleset;
        string title = match.Session.Winner is int w
            ? ruleset.HasScore
                ? string.Create(CultureInfo.InvariantCulture, $"{names[w]} wins {ruleset.TheGame} {score[w]}-{score[1 - w]}")
                : $"{names[w]} wins {ruleset.TheGame}"
            : $"{Capitalised(ruleset.TheGame)} ends without a winner";
        return new ResultPanel(title, names, PlayerStats.Of(ruleset, game.Shots), match.Session.GamesWon) { BreakWord = ruleset.BreakWord, GameWord = ruleset.GameWord, ScoreSheet = ruleset.HasInnings };
    }

    /// <summary>
    /// The break of <paramref name="player"/>'s visit now at the table: 0 before they scored, or when
    /// the turn is not theirs (<see cref="Ruleset.Visits"/>).
    /// </summary>
    public static int CurrentBreak(Ruleset ruleset, IReadOnlyList<MatchShot> shots, int player)
    {
        ArgumentNullException.ThrowIfNull(ruleset);
        ArgumentNullException.ThrowIfNull(shots);
        var last = ruleset.Visits(shots.Select(s => (s.Before.Shooter, s.Ruling))).LastOrDefault();
        return last.Open && last.Player == player ? last.Break : 0;
    }

    /// <summary>The words with their first letter in capitals ("the frame" to "The frame").</summary>
    internal static string Capitalised(string words) => words.Length == 0 ? words : string.Concat(words[..1].ToUpperInvariant(), words.AsSpan(1));

    /// <summary>The game's short name.</summary>
    public static string GameName(GameRules rules) => Ruleset.For(rules).ShortName;

    // Fouls in a row as they stand after the last shot: a game that ended on a third foul shows
    // three, not the two its state had before that shot.
    private static PerPlayer<int> FoulsInRow(MatchNode match, IReadOnlyList<MatchShot> shots)
    {
        var fouls = match.Session.State.FoulsInRow;
        if (match.Session.IsOver && shots.Count > 0 && shots[^1] is { Ruling.Legal: false } last)
        {
            int p = last.Before.Shooter;
            fouls = fouls.With(p, last.Before.FoulsInRow[p] + 1);
        }
        return fouls;
    }

    private static string Status(MatchNode match, PhysicsNode physics, string? computerStatus)
    {
        var state = match.Session.State;
        if (match.Session.IsOver)
        {
            return match.Session.RematchIn is double left ? $"Next game in {Math.Max(1, (int)Math.Ceiling(left))} s"
                : match.IsNetworked ? "Game over: M: menu" : "Game over: Enter or click Rematch; M: menu";
        }
        if (computerStatus is not null)
        {
            return computerStatus;
        }
        if (match.Session.IsComputerActing)
        {
            // "(computer)" only where the name does not say so already (as on the cards).
            string who = state.ShooterName.StartsWith("Computer", StringComparison.Ordinal) ? state.ShooterName : $"{state.ShooterName} (computer)";
            return physics.IsRolling ? $"{who} shoots." : $"{who} is at the table.";
        }
        if (match.Session.IsRemoteActing && !physics.IsRolling)
        {
            // Over the network: the other player's turn, played at their machine.
            return match.Session.PendingOptions.Count > 0 ? $"{state.ShooterName} chooses (online)." : $"{state.ShooterName} is at the table (online).";
        }
        if (physics.IsRolling)
        {
            return "Balls rolling: the view only.";
        }
        if (match.Session.PendingOptions.Count > 0)
        {
            var options = match.Session.PendingOptions.Select((o, i) => $"[{i + 1}] {o.ToName()}");
            return $"{state.ShooterName} chooses: {string.Join("  ", options)}";
        }
        var parts = new List<string>();
        if (match.NeedsCall)
        {
            parts.Add(match.Call.CurrentCall is { } c ? $"Call: {physics.Simulation.BallSet.NameOf(c.Ball)} in {c.Pocket.ToName()} (B, C)" : "Call: none (B, C)");
        }
        if (match.NeedsNomination)
        {
            string ball = match.Call.CurrentNomination is { } n ? BallSet.NameOfAny(n.Ball) : "none";
            parts.Add(SnookerPart.Of(state).FreeBall ? $"FREE BALL: nominate {ball} (B, click a ball)" : $"Nominate: {ball} (B, click a ball)");
        }
        if (physics.BallInHand)
        {
            parts.Add($"ball in hand ({MatchLines.HandWords(physics.HandRegion)}): M, drag");
        }
        if (match.PushOut)
        {
            parts.Add("PUSH-OUT");
        }
        else if (match.Session.Ruleset.MayPushOut(state))
        {
            parts.Add("O push-out");
        }
        parts.Add("Space shoots, G hint");
        // The shooter's card is marked: the line need not name them.
        return string.Join(";  ", parts);
    }

    // "Sound: off (no audio device)" and the like, shorter for the corner.
    private static string SoundWord(string sound) => sound.Replace("Sound: off (no audio device)", "no sound", StringComparison.Ordinal)
        .Replace("Sound: ", "sound ", StringComparison.Ordinal).Replace("audio device", "device", StringComparison.Ordinal);
}
