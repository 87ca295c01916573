namespace Billiards.Core.Balls;

/// <summary>The motion state of a ball; a ball is in exactly one at a time.</summary>
public enum MotionState : byte
{
    /// <summary>At rest: no linear velocity and no spin.</summary>
    Stationary,
    /// <summary>No linear velocity, spinning about the vertical axis only.</summary>
    Spinning,
    /// <summary>The contact point slips on the cloth.</summary>
    Sliding,
    /// <summary>Rolling without slip.</summary>
    Rolling,
    /// <summary>In a pocket; out of play.</summary>
    Pocketed,
    /// <summary>In the air (standard model): on a parabola under gravity, spin constant, until it lands.</summary>
    Airborne,
    /// <summary>Left the table over a rail; out of play, at its last position.</summary>
    OffTable,
}

/// <summary>Names of motion states as the result format writes them.</summary>
public static class MotionStateNames
{
    /// <summary>"stationary", "spinning", "sliding", "rolling", "pocketed", "airborne" or "off-table".</summary>
    public static string ToName(this MotionState state) => state switch
    {
        MotionState.Stationary => "stationary",
        MotionState.Spinning => "spinning",
        MotionState.Sliding => "sliding",
        MotionState.Rolling => "rolling",
        MotionState.Pocketed => "pocketed",
        MotionState.Airborne => "airborne",
        MotionState.OffTable => "off-table",
        _ => throw new ArgumentOutOfRangeException(nameof(state)),
    };
}
