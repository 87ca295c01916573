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
}

/// <summary>Names of motion states as the result format writes them.</summary>
public static class MotionStateNames
{
    /// <summary>"stationary", "spinning", "sliding", "rolling" or "pocketed".</summary>
    public static string ToName(this MotionState state) => state switch
    {
        MotionState.Stationary => "stationary",
        MotionState.Spinning => "spinning",
        MotionState.Sliding => "sliding",
        MotionState.Rolling => "rolling",
        MotionState.Pocketed => "pocketed",
        _ => throw new ArgumentOutOfRangeException(nameof(state)),
    };
}
