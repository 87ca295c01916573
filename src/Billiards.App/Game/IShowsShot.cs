using Billiards.Core.Cue;
using Billiards.Core.Physics;

namespace Billiards.App.Game;

/// <summary>
/// A node that shows a shot played again (the instant replay, a game record's playback) in place
/// of the table at rest: the sound follows the shot it shows (<see cref="Audio.AudioNode"/>).
/// </summary>
public interface IShowsShot
{
    /// <summary>The shot shown now, at its <see cref="ShotReplay.Time"/>; null while none is shown.</summary>
    ShotReplay? ShownShot { get; }

    /// <summary>The strike of the shot shown (its tip offset tells a miscue), or null when unknown.</summary>
    ShotSpec? ShownStrike { get; }

    /// <summary>How many times the shown time has been set by hand (scrubbed, stepped to a collision): the sound skips what such a jump passes over.</summary>
    int ShownSeeks { get; }
}
