using Billiards.Core.Balls;
using Billiards.Core.Table;

namespace Billiards.App.Hud;

/// <summary>A ball and a pocket as a player says them: "the red", not the set's "red-11"; no "none pocket".</summary>
public static class BallWords
{
    /// <summary>The ball's name for the player: a snooker red is "red" (the fifteen are one to the player), any other ball its set's name.</summary>
    public static string Of(BallId ball)
    {
        string name = ball.ToString();
        int dash = name.IndexOf('-', StringComparison.Ordinal);
        return dash > 0 && name.StartsWith("red", StringComparison.Ordinal) ? name[..dash] : name;
    }

    /// <summary>"the 3 in the foot-left pocket", or "the green" when no pocket is named (a snooker nomination).</summary>
    public static string Pot(BallId ball, PocketId pocket) =>
        pocket == PocketId.None ? $"the {Of(ball)}" : $"the {Of(ball)} in the {pocket.ToName()} pocket";
}
