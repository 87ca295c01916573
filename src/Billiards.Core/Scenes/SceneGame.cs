using Billiards.Core.Balls;
using Billiards.Core.Rules;

namespace Billiards.Core.Scenes;

/// <summary>
/// The one place that decides which game a scene is: the loader (for the scene's ball set), the
/// window, <c>play</c>, <c>suggest</c> and the tests ask it rather than reading the fields themselves.
/// </summary>
public static class SceneGame
{
    /// <summary>
    /// The game of a scene whose game block names <paramref name="gameBlockRules"/> and whose
    /// top-level "rules" is <paramref name="rules"/> (either may be absent): the game block's, else
    /// "rules"; null when neither names a registered game.
    /// </summary>
    public static GameRules? Of(string? gameBlockRules, string? rules) =>
        RuleNames.TryParseGame(gameBlockRules, out var fromBlock) ? fromBlock
        : RuleNames.TryParseGame(rules, out var named) ? named
        : (GameRules?)null;

    /// <summary>
    /// The balls of a scene that names no game, from its rack's game (<paramref name="rackGame"/>,
    /// e.g. "snooker") or else its table's preset (<paramref name="tablePreset"/>): the set of the
    /// registered game of that name, else of the first registered game played on that table
    /// (<see cref="Ruleset.TablePreset"/>: the carom table's is three-cushion's), else pool's.
    /// </summary>
    public static BallSet BallSetOf(string? rackGame, string? tablePreset)
    {
        if (RuleNames.TryParseGame(rackGame, out var racked))
        {
            return Ruleset.For(racked).BallSet;
        }
        return Ruleset.All.FirstOrDefault(r => r.TablePreset == tablePreset)?.BallSet ?? BallSet.Pool;
    }

    /// <summary>The game of a loaded scene (its game block's rules, else its "rules"), or null for a scene of no game.</summary>
    public static GameRules? Of(Scene scene)
    {
        ArgumentNullException.ThrowIfNull(scene);
        return Of(scene.Game?.Rules.Name, scene.Rules);
    }
}
