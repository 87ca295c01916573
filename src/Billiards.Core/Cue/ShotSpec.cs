namespace Billiards.Core.Cue;

/// <summary>
/// A cue strike on the cue ball: cue speed (m/s), aim angle (deg, from +x counter-clockwise),
/// tip offset [side, height] as fractions of R (side positive to the right of the aim line seen
/// from behind the cue, height positive above centre), and cue elevation (deg above the bed).
/// </summary>
public sealed record ShotSpec(double Speed, double AimDeg, double TipSide = 0, double TipHeight = 0, double ElevationDeg = 0);
