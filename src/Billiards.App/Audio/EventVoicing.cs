using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;

namespace Billiards.App.Audio;

/// <summary>
/// Turns a shot's physics events into <see cref="SoundCue"/>s, the same way in the game and in
/// <c>render-audio</c>: which sound, how hard, where, and the seed of its variations. It remembers
/// the jaw hits of the shot, so a ball that drops after rattling in the jaws drops with a rattle.
/// </summary>
public sealed class EventVoicing
{
    /// <summary>Tip offset from the ball's centre (fraction of R) beyond which the tip slides off: a miscue.</summary>
    public const double MiscueTipOffset = 0.5;

    /// <summary>How long before its drop a jaw hit makes the ball rattle (s).</summary>
    public const double RattleWindow = 0.3;

    /// <summary>Seed of the whole game's variations; each cue's seed mixes in its event's ordinal and balls.</summary>
    public const uint BaseSeed = 0x5EED_B177;

    private readonly Func<EventKind, int, string> _featureName;
    private readonly Dictionary<int, double> _lastJawHit = [];
    private int _ordinal;

    /// <summary>Creates the voicing of one simulation's events.</summary>
    /// <param name="featureName">Names cushions and pockets (<see cref="Simulation.FeatureName"/>); jaws contain "jaw".</param>
    public EventVoicing(Func<EventKind, int, string> featureName) => _featureName = featureName;

    /// <summary>The cue of one event, or null for an event that makes no sound.</summary>
    /// <param name="e">The event.</param>
    /// <param name="position">Where it happened (m): the ball's centre, the middle of two balls.</param>
    /// <param name="shot">The strike of the shot, for the tip offset of a cue strike; null when unknown.</param>
    public SoundCue? Voice(in SimEvent e, Vec3 position, ShotSpec? shot)
    {
        if (e.Kind == EventKind.CueStrike)
        {
            // A new shot: its rattles and its variations start afresh, as in a render of it alone.
            _lastJawHit.Clear();
            _ordinal = 0;
        }
        uint seed = Noise.Mix(BaseSeed ^ (uint)(_ordinal++ * 0x9E3779B1u) ^ (uint)(e.A.Value << 8) ^ (uint)(e.B.Value << 16) ^ (uint)e.Kind);
        switch (e.Kind)
        {
            case EventKind.CueStrike:
                double tip = shot is null ? 0 : Math.Sqrt((shot.TipSide * shot.TipSide) + (shot.TipHeight * shot.TipHeight));
                return new SoundCue(e.Time, tip > MiscueTipOffset ? SoundKind.Miscue : SoundKind.CueStrike, e.Speed, position, false, seed);
            case EventKind.BallBall:
                return new SoundCue(e.Time, SoundKind.BallClick, e.Speed, position, false, seed);
            case EventKind.BallCushion:
                if (IsJaw(e))
                {
                    _lastJawHit[e.A.Value] = e.Time;
                    return new SoundCue(e.Time, SoundKind.JawKnock, e.Speed, position, false, seed);
                }
                return new SoundCue(e.Time, SoundKind.CushionThud, e.Speed, position, false, seed);
            case EventKind.BallPocket:
                bool rattle = _lastJawHit.TryGetValue(e.A.Value, out double hit) && e.Time - hit <= RattleWindow;
                return new SoundCue(e.Time, SoundKind.PocketDrop, e.Speed, position, rattle, seed);
            case EventKind.BallTable:
                // A landing from the air (the event's speed is the vertical impact speed), also the
                // cue ball driven into the slate by a jump stroke.
                return new SoundCue(e.Time, SoundKind.TableLanding, e.Speed, position, false, seed);
            default:
                return null;
        }
    }

    private bool IsJaw(in SimEvent e) => _featureName(e.Kind, e.Feature).Contains("jaw", StringComparison.OrdinalIgnoreCase);
}
