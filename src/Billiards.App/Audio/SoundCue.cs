using Billiards.Core.Mathematics;

namespace Billiards.App.Audio;

/// <summary>What a sound is: each kind has its own synthesis in <see cref="VoiceSynth"/>.</summary>
public enum SoundKind
{
    /// <summary>Two balls collide: a short, bright phenolic click.</summary>
    BallClick,

    /// <summary>A ball hits a cushion's rubber: a low, damped thud.</summary>
    CushionThud,

    /// <summary>A ball hits a pocket jaw: a harder, higher knock than a cushion.</summary>
    JawKnock,

    /// <summary>The cue's leather tip strikes the cue ball: a dull tock.</summary>
    CueStrike,

    /// <summary>The tip slides off the ball (tip offset beyond <see cref="EventVoicing.MiscueTipOffset"/>): a scrape and a thin ring.</summary>
    Miscue,

    /// <summary>A ball drops into a pocket, then rolls along the return under the table.</summary>
    PocketDrop,

    /// <summary>A ball in the air lands on the bed: the cloth-covered slate's dull thump, louder the faster it comes down.</summary>
    TableLanding,
}

/// <summary>
/// One sound to play, made from one physics event by <see cref="EventVoicing"/>.
/// </summary>
/// <param name="Time">Simulated time of the event (s); the sound starts exactly then.</param>
/// <param name="Kind">Which synthesis.</param>
/// <param name="Speed">Impact speed (m/s): normal approach speed, the cue's speed, or the speed of the drop.</param>
/// <param name="Position">Where it sounds, in table coordinates (m).</param>
/// <param name="Rattle">For a pocket drop: the ball hit the jaws just before, so it rattles in the pocket.</param>
/// <param name="Seed">Seed of the small variations (pitch, decay, level, noise) of this one sound.</param>
public readonly record struct SoundCue(double Time, SoundKind Kind, double Speed, Vec3 Position, bool Rattle, uint Seed);
