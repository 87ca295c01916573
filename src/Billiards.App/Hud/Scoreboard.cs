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
/// <param name="BestRun">The most balls pocketed in one visit to the table.</param>
public readonly record struct PlayerStats(int Shots, int Pots, int Fouls, int BestRun)
{
    /// <summary>The most points scored in one visit (snooker's highest break).</summary>
    public int HighestBreak { get; init; }

    /// <summary>Each player's numbers from a game's shots.</summary>
    public static PerPlayer<PlayerStats> Of(IReadOnlyList<MatchShot> shots)
    {
        ArgumentNullException.ThrowIfNull(shots);
        var stats = new PlayerStats[2];
        int run = 0, points = 0;
        int? visitor = null;
        foreach (var shot in shots)
        {
            int p = shot.Before.Shooter;
            if (visitor != p)
            {
                visitor = p;
                (run, points) = (0, 0);
            }
            int pots = shot.Ruling.Legal ? shot.Ruling.Pocketed.Count : 0;
            run += pots;
            points += shot.Ruling.Legal ? shot.Ruling.Points : 0;
            var s = stats[p];
            stats[p] = new PlayerStats(s.Shots + 1, s.Pots + pots, s.Fouls + (shot.Ruling.Legal ? 0 : 1), Math.Max(s.BestRun, run)) { HighestBreak = Math.Max(s.HighestBreak, points) };
            if (!shot.Ruling.Continue)
            {
                visitor = null;
            }
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
    /// <summary>True for snooker: the panel speaks of breaks (points in a visit) and frames.</summary>
    public bool Snooker { get; init; }

    /// <summary>The panel's rows: a label and each player's figure.</summary>
    public IReadOnlyList<(string Label, string First, string Second)> Rows =>
    [
        ("Shots", Text(Stats.First.Shots), Text(Stats.Second.Shots)),
        ("Pots", Text(Stats.First.Pots), Text(Stats.Second.Pots)),
        ("Fouls", Text(Stats.First.Fouls), Text(Stats.Second.Fouls)),
        Snooker
            ? ("Highest break", Text(Stats.First.HighestBreak), Text(Stats.Second.HighestBreak))
            : ("Best run", Text(Stats.First.BestRun), Text(Stats.Second.BestRun)),
        (Snooker ? "Frames won" : "Games won", Text(Games.First), Text(Games.Second)),
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
        var state = match.State;
        var onTable = physics.ObjectBallsOnTable();
        var shots = match.Game?.Shots ?? [];
        var fouls = FoulsInRow(match, shots);
        var cards = new PlayerCard[2];
        bool snooker = state.Rules == GameRules.Snooker;
        for (int p = 0; p < 2; p++)
        {
            var target = match.Ruleset.Target(state, p, onTable);
            if (snooker && p == state.Shooter && match.CurrentNomination is { } nominated)
            {
                // The colour or the free ball nominated now, before the strike makes it the state's call.
                string ballName = BallSet.NameOfAny(nominated.Ball);
                target = state.FreeBall
                    ? target with { Text = string.Create(CultureInfo.InvariantCulture, $"{state.Score[p]}, free ball: {ballName}") }
                    : match.Ruleset.Target(state with { Call = nominated }, p, onTable);
            }
            var detail = new List<string>();
            if (snooker)
            {
                // Snooker: the target's words carry the score and the ball on; the break and the snookers needed beside them.
                if (p == state.Shooter && !match.IsOver)
                {
                    detail.Add(string.Create(CultureInfo.InvariantCulture, $"break {SnookerLines.CurrentBreak(shots, p)}"));
                }
                if (!match.IsOver && SnookerLines.NeedsSnookers(state, p, onTable))
                {
                    detail.Add("needs snookers");
                }
            }
            else if (match.Ruleset.HasScore)
            {
                detail.Add(string.Create(CultureInfo.InvariantCulture, $"score {state.Score[p]} of {state.Target}"));
            }
            // Only where a third foul in a row costs something (not 8-ball).
            if (match.Ruleset.HasThreeFouls && fouls[p] > 0)
            {
                detail.Add(string.Create(CultureInfo.InvariantCulture, $"fouls in a row {fouls[p]}"));
            }
            string name = match.Players[p].IsHuman || state.Players[p].StartsWith("Computer", StringComparison.Ordinal) ? state.Players[p] : $"{state.Players[p]} (computer)";
            if (snooker && match.IsOver)
            {
                // The frame is over: the final score, no ball on.
                target = new HudTarget(string.Create(CultureInfo.InvariantCulture, $"{state.Score[p]}"), []);
            }
            cards[p] = new PlayerCard(name, p == state.Shooter && !match.IsOver, target.Text, [.. target.Balls.Select(b => b.Value)], string.Join("  ", detail));
        }
        string remaining = snooker ? string.Create(CultureInfo.InvariantCulture, $"  remaining {SnookerLines.Remaining(state, onTable)}") : "";
        string title = $"{GameName(state.Rules)}  shot {state.Shot}{remaining}  {(snooker ? "frames" : "games")} {match.GamesWon.First}-{match.GamesWon.Second}{(paused ? "  PAUSED (P)" : "")}";
        string corner = sound is null ? "H help" : $"H help  {SoundWord(sound)}";
        var rulings = shots.Select(s => s.Ruling.Message).Reverse().Where(m => m != match.Message).Take(LogLength).ToList();
        return new Scoreboard(title, corner, cards, Status(match, physics, computerStatus), match.Message, rulings);
    }

    /// <summary>The result panel, or null while the game is on.</summary>
    public static ResultPanel? Result(MatchNode match)
    {
        ArgumentNullException.ThrowIfNull(match);
        if (!match.IsOver || match.Game is not { } game)
        {
            return null;
        }
        var names = match.State.Players;
        var score = match.State.Score;
        string title = match.Winner is int w
            ? match.Rules == GameRules.Snooker
                ? string.Create(CultureInfo.InvariantCulture, $"{names[w]} wins the frame {score[w]}-{score[1 - w]}")
                : $"{names[w]} wins the {GameName(match.Rules)} game"
            : $"The {GameName(match.Rules)} game ends without a winner";
        return new ResultPanel(title, names, PlayerStats.Of(game.Shots), match.GamesWon) { Snooker = match.Rules == GameRules.Snooker };
    }

    /// <summary>The game's short name.</summary>
    public static string GameName(GameRules rules) => Ruleset.For(rules).ShortName;

    // Fouls in a row as they stand after the last shot: a game that ended on a third foul shows
    // three, not the two its state had before that shot.
    private static PerPlayer<int> FoulsInRow(MatchNode match, IReadOnlyList<MatchShot> shots)
    {
        var fouls = match.State.FoulsInRow;
        if (match.IsOver && shots.Count > 0 && shots[^1] is { Ruling.Legal: false } last)
        {
            int p = last.Before.Shooter;
            fouls = fouls.With(p, last.Before.FoulsInRow[p] + 1);
        }
        return fouls;
    }

    private static string Status(MatchNode match, PhysicsNode physics, string? computerStatus)
    {
        var state = match.State;
        if (match.IsOver)
        {
            return match.RematchIn is double left ? $"Next game in {Math.Max(1, (int)Math.Ceiling(left))} s" : "Game over: Enter or click Rematch; M: menu";
        }
        if (computerStatus is not null)
        {
            return computerStatus;
        }
        if (match.IsComputerActing)
        {
            // "(computer)" only where the name does not say so already (as on the cards).
            string who = state.ShooterName.StartsWith("Computer", StringComparison.Ordinal) ? state.ShooterName : $"{state.ShooterName} (computer)";
            return physics.IsRolling ? $"{who} shoots." : $"{who} is at the table.";
        }
        if (physics.IsRolling)
        {
            return "Balls rolling: the view only.";
        }
        if (match.PendingOptions.Count > 0)
        {
            var options = match.PendingOptions.Select((o, i) => $"[{i + 1}] {o.ToName()}");
            return $"{state.ShooterName} chooses: {string.Join("  ", options)}";
        }
        var parts = new List<string>();
        if (match.NeedsCall)
        {
            parts.Add(match.CurrentCall is { } c ? $"Call: {physics.Simulation.BallSet.NameOf(c.Ball)} in {c.Pocket.ToName()} (B, C)" : "Call: none (B, C)");
        }
        if (match.NeedsNomination)
        {
            string ball = match.CurrentNomination is { } n ? BallSet.NameOfAny(n.Ball) : "none";
            parts.Add(state.FreeBall ? $"FREE BALL: nominate {ball} (B, click a ball)" : $"Nominate: {ball} (B, click a ball)");
        }
        if (physics.BallInHand)
        {
            parts.Add($"ball in hand ({MatchLines.HandWords(physics.HandRegion)}): M, drag");
        }
        if (state.PushOut)
        {
            parts.Add("PUSH-OUT");
        }
        else if (match.Ruleset.MayPushOut(state))
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

/// <summary>Snooker's figures on the scoreboard: the break of the player at the table, the points remaining and who needs snookers (rules.md "Snooker").</summary>
public static class SnookerLines
{
    /// <summary>
    /// The points of <paramref name="player"/>'s visit now at the table (their break): the points of
    /// their shots since the turn last came to them, 0 before they scored.
    /// </summary>
    public static int CurrentBreak(IReadOnlyList<MatchShot> shots, int player)
    {
        ArgumentNullException.ThrowIfNull(shots);
        int points = 0;
        for (int i = shots.Count - 1; i >= 0 && shots[i].Before.Shooter == player && shots[i].Ruling.Continue; i--)
        {
            points += shots[i].Ruling.Points;
        }
        return points;
    }

    /// <summary>The points still on the table for the player at the table (<see cref="SnookerRuleset.PointsRemaining"/>).</summary>
    public static int Remaining(GameState state, IReadOnlyCollection<BallId> objectBalls) =>
        SnookerRuleset.PointsRemaining(SnookerRuleset.BallOnOf(state), objectBalls);

    /// <summary>True when <paramref name="player"/> is behind by more than the points remaining.</summary>
    public static bool NeedsSnookers(GameState state, int player, IReadOnlyCollection<BallId> objectBalls)
    {
        ArgumentNullException.ThrowIfNull(state);
        return state.Score[1 - player] - state.Score[player] > Remaining(state, objectBalls);
    }
}
