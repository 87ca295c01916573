namespace Billiards.App.Input.Modes;

/// <summary>The seed's control modes (seed 4.4), each switched by a key.</summary>
public enum InputMode
{
    /// <summary>v: left-drag orbits the camera, right-drag zooms (the default, and the only mode while balls roll).</summary>
    View,
    /// <summary>s: left-drag forward and back moves the cue; passing the start line strikes.</summary>
    Shot,
    /// <summary>e: left-drag moves the tip's offset on the cue ball (effet).</summary>
    Spin,
    /// <summary>m: left-drag moves the cue ball; the camera follows.</summary>
    Move,
}
