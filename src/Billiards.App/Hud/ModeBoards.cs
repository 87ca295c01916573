using System.Globalization;
using Billiards.App.Game;
using Billiards.Core.Balls;
using Billiards.Core.Rules;

namespace Billiards.App.Hud;

/// <summary>
/// The match scoreboard's style for the modes without a match: practice and drills (the drill's name,
/// goal and attempts in the card, the next ball in the status line) and a record's replay (the
/// players' cards as the match stood, "shot 3 of 5" counted from 1). The developer lines stay behind F2.
/// </summary>
public static class ModeBoards
{
    /// <summary>The scoreboard of practice or a drill now.</summary>
    public static Scoreboard Of(PracticeNode practice, string? sound)
    {
        ArgumentNullException.ThrowIfNull(practice);
        var c = CultureInfo.InvariantCulture;
        string power = string.Create(c, $"power {practice.Power:0.00} m/s (W, Q);  Space shoots;  F6 sensitivity");
        string corner = Corner(sound);
        if (practice.Drill is not { } drill)
        {
            var free = new PlayerCard("Practice", true, "no referee", [], "");
            return new Scoreboard("Practice: any ball, any shot", corner, [free],
                $"M and drag a ball;  Insert adds, Delete removes;  Backspace retries;  F5 saves, F9 loads;  {power}", practice.Message, []);
        }
        var attempt = practice.Attempt;
        var record = practice.Record;
        string target = record is { } r ? string.Create(c, $"attempts {r.Attempts}, made {r.Successes}") : "first attempt";
        string best = record?.BestDistance is double b ? string.Create(c, $"best {b * 100:0.0} cm") : record is { BestPotted: > 0 } && drill.Sequence.Count > 1 ? string.Create(c, $"best {record.BestPotted} of {drill.Sequence.Count}") : "";
        var balls = attempt is null ? [] : drill.Sequence.Skip(attempt.Potted).Select(id => id.Value).ToList();
        var card = new PlayerCard($"Drill: {drill.Title}", attempt?.Outcome is null, target, balls, best);
        string status = attempt?.Outcome is { } o
            ? $"{(o.Success ? "Made it" : "Missed")}: Enter again, Backspace retries the shot"
            : attempt?.Next is { } next
                ? drill.Carom ? $"{PracticeNode.CaromGoal(drill)};  {power}"
                : drill.Sequence.Count > 1 ? string.Create(c, $"Next: the {next} ({attempt.Potted + 1} of {drill.Sequence.Count});  {power}") : $"Pot the {next};  {power}"
                : power;
        string message = attempt?.Outcome is { } outcome ? $"{(outcome.Success ? "Success" : "Failed")}: {outcome.Reason}" : practice.Message ?? $"Goal: {drill.Goal}";
        return new Scoreboard($"Drill: {drill.Title}", corner, [card], status, message, attempt?.Outcome is null ? [] : [$"Goal: {drill.Goal}"]);
    }

    /// <summary>The scoreboard of a record's replay now, or null before the replay is ready.</summary>
    public static Scoreboard? Of(ReplayNode replay, PhysicsNode physics, string? sound)
    {
        ArgumentNullException.ThrowIfNull(replay);
        ArgumentNullException.ThrowIfNull(physics);
        if (replay.Match is not { } match)
        {
            return null;
        }
        var state = match.State;
        var ruleset = match.Ruleset;
        var onTable = physics.ObjectBallsOnTable();
        var cards = new PlayerCard[2];
        for (int p = 0; p < 2; p++)
        {
            var target = ruleset.Target(state, p, onTable);
            cards[p] = new PlayerCard(state.Players[p], p == state.Shooter && !match.IsOver, target.Text, [.. target.Balls.Select(x => x.Value)], "");
        }
        var (shot, of) = replay.Counter;
        string title = replay.Finished
            ? string.Create(CultureInfo.InvariantCulture, $"Replay of {ruleset.ShortName}: all {of} shots shown")
            : string.Create(CultureInfo.InvariantCulture, $"Replay of {ruleset.ShortName}: shot {shot} of {of}");
        string status = replay.Finished
            ? "The end of the record: PageUp shows a shot again;  Esc, then Q, leaves"
            : $"{(replay.IsShowing ? $"{state.ShooterName} shoots" : $"{state.ShooterName} is at the table")};  PageUp, PageDown: shots;  Esc: menu";
        return new Scoreboard(title, Corner(sound), cards, status, replay.LastRuling, []);
    }

    private static string Corner(string? sound) => sound is null ? "H help" : "H help";
}
