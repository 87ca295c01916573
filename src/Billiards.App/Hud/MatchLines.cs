using System.Globalization;
using System.Text;
using Billiards.App.Game;
using Billiards.Core.Balls;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.App.Hud;

/// <summary>
/// The match's lines on the HUD: the players with the shooter marked, each one's group or target
/// and the balls still needed, the 14.1 score, fouls in a row, the shot count, the call, the
/// pending options with their keys, the ruling's message and the game's end.
/// </summary>
public static class MatchLines
{
    /// <summary>Appends the match's lines for <paramref name="match"/> with the table's balls.</summary>
    public static void Add(List<string> lines, MatchNode match, PhysicsNode physics, string? computerStatus = null, List<Rendering.HudIcon>? icons = null)
    {
        ArgumentNullException.ThrowIfNull(lines);
        ArgumentNullException.ThrowIfNull(match);
        ArgumentNullException.ThrowIfNull(physics);
        var state = match.Session.State;
        var onTable = physics.ObjectBallsOnTable();
        // The ruleset's own words: snooker's frames, not games.
        lines.Add($"{state.Rules.ToName()}  shot {state.Shot}  {match.Session.Ruleset.GameWord}s {match.Session.GamesWon.First}-{match.Session.GamesWon.Second}");
        for (int p = 0; p < 2; p++)
        {
            string mark = p == state.Shooter && !match.Session.IsOver ? "> " : "  ";
            var sb = new StringBuilder();
            var target = match.Session.Ruleset.Target(state, p, onTable);
            sb.Append(CultureInfo.InvariantCulture, $"{mark}{state.Players[p]}: {target.Text}");
            // A game with a ball on (snooker) has the score in its target's words and no score to reach.
            if (match.Session.Ruleset.HasScore && !match.Session.Ruleset.HasBallOn)
            {
                sb.Append(CultureInfo.InvariantCulture, $"  score {state.Score[p]} of {state.Target}");
            }
            if (match.Session.Ruleset.HasThreeFouls && state.FoulsInRow[p] > 0)
            {
                sb.Append(CultureInfo.InvariantCulture, $"  fouls in a row {state.FoulsInRow[p]}");
            }
            lines.Add(sb.ToString());
            foreach (var ball in target.Balls)
            {
                icons?.Add(new Rendering.HudIcon(lines.Count - 1, ball.Value));
            }
        }
        if (match.Session.IsOver)
        {
            string next = match.Session.RematchIn is double left ? $"Next game in {Math.Max(1, (int)Math.Ceiling(left))} s" : "Enter: rematch";
            lines.Add(match.Session.Winner is int w ? $"GAME OVER: {state.Players[w]} wins. {next}" : $"GAME OVER. {next}");
        }
        else if (computerStatus is not null)
        {
            lines.Add(computerStatus);
        }
        else if (match.Session.IsComputerActing)
        {
            lines.Add($"{state.ShooterName} (computer) is at the table.");
        }
        else if (match.Session.PendingOptions.Count > 0)
        {
            var options = match.Session.PendingOptions.Select((o, i) => $"[{i + 1}] {o.ToName()}");
            lines.Add($"{state.ShooterName} chooses: {string.Join("  ", options)}");
        }
        else
        {
            if (physics.BallInHand)
            {
                lines.Add($"Ball in hand ({HandWords(physics.HandRegion)}): M and drag to place");
            }
            string push = match.PushOut ? "  PUSH-OUT" : "";
            string pushKey = match.Session.Ruleset.MayPushOut(state) ? "  O: push-out" : "";
            // Only a shot the rules call shows a call.
            string call = match.NeedsNomination ? $"Nominate: {(match.Call.CurrentNomination is { } n ? physics.Simulation.BallSet.NameOf(n.Ball) : "none")} (B)  "
                : !match.NeedsCall ? "" : match.Call.CurrentCall is { } c ? $"Call: {physics.Simulation.BallSet.NameOf(c.Ball)} in {c.Pocket.ToName()} (B ball, C pocket)  " : "Call: none (B ball, C pocket)  ";
            lines.Add(string.Create(CultureInfo.InvariantCulture, $"{call}Power {match.Power:0.00} m/s (Q/W, Space shoots, G hint){push}{pushKey}"));
        }
        // This game's: a rematch starts without the last game's ruling.
        if (match.Session.Game?.LastRuling is { } last)
        {
            lines.Add($"Last ruling: {last.Message}");
        }
        if (match.Session.Message is { } message && message != match.Session.Game?.LastRuling?.Message)
        {
            lines.Add(message);
        }
    }

    /// <summary>Where a ball in hand goes, in a few words: "kitchen", "in the D", "anywhere".</summary>
    public static string HandWords(Core.Setup.PlacementRegion region) => region switch
    {
        Core.Setup.PlacementRegion.Kitchen => "kitchen",
        Core.Setup.PlacementRegion.D => "in the D",
        _ => "anywhere",
    };
}
