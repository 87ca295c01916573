namespace Billiards.App.Hud;

/// <summary>The help overlay: every key and mouse action of the game.</summary>
public static class HelpText
{
    /// <summary>
    /// The overlay's lines for a game: practice's keys only in practice, the match's everywhere but
    /// in practice, so that the overlay fits the window.
    /// </summary>
    public static IReadOnlyList<string> For(bool match, bool practice)
    {
        var lines = new List<string>();
        bool keep = true;
        foreach (string line in Lines)
        {
            if (!line.StartsWith(' '))
            {
                // A scene played without a match or practice (a physics scene) keeps the match's keys, as before.
                keep = (match || !practice || !line.StartsWith("Match", StringComparison.Ordinal)) && (practice || !line.StartsWith("Practice", StringComparison.Ordinal));
            }
            if (keep)
            {
                lines.Add(line);
            }
        }
        return lines;
    }

    /// <summary>The overlay's lines: every section.</summary>
    public static IReadOnlyList<string> Lines { get; } =
    [
        "Modes",
        "  V            view: left-drag orbits the camera (Shift: fine), right-drag or wheel zooms",
        "  S            shot: hold the left button, pull the mouse back, push it forward",
        "               past the start to strike; the push's speed is the shot's (meter below)",
        "  E            spin: left-drag moves the tip on the cue ball",
        "  M            move the cue ball: left-drag (Shift: fine), arrows nudge it; after a scratch",
        "               the cue ball is in hand anywhere on the table",
        "  While balls roll only view mode works; the camera looks down on the table.",
        "  T            overhead view / back to the cue ball",
        "Cue",
        "  Up / Down    raise / lower the cue (also PageUp / PageDown, or the wheel in shot",
        "               and spin mode); over a rail or a ball the cue is raised to clear it",
        "Match (the referee's rulings pass the turn)",
        "  Left / Right aim 1 deg; A / D or Shift aim 0.1 deg (held keys repeat, faster and faster)",
        "  X            aim at the called ball's ghost ball",
        "  Q / W        shot power down / up; Space shoots at that power",
        "  B / C        call another ball / another pocket (or click a ball, then a pocket)",
        "  G            hint: the computer's shot for you (placement, call, aim, power, spin, elevation)",
        "  L            aim line: path, ghost ball, object ball's direction (on / off)",
        "  O            declare a push-out (9-ball and 10-ball, the shot after the break)",
        "  1 .. 5       take one of the incoming player's options (or click its button)",
        "  Enter        rematch once a game is over (the other player breaks); M: the start menu",
        "Practice and drills (play --practice, play --drill NAME, or the start menu)",
        "  M, then drag any ball follows the cursor; Insert / Delete add / remove the ball under it",
        "  Space, Q / W shoot at the power, power down / up; Left / Right aim (as in a match)",
        "  Backspace    retry the last shot (balls, aim, power, spin, elevation); Enter: the start",
        "  F5 / F9      save the position with the cue's shot as a scene / load it back",
        "  F6 / F7      shot sensitivity: how often the shot pots with a level's error / the level",
        "Replay and take-back",
        "  R            instant replay (R or Escape leaves): 1-4 speed 1x 1/2 1/4 1/8, Space pause,",
        "               Left / Right scrub (Shift fine), N / Shift+N next / previous collision",
        "  K, Z         tracking lines; take the last shot back (practice; a game with take-backs)",
        "  PageUp/Down  replay GAME.json: the previous / next shot",
        "Game",
        "  P            pause / resume",
        "  N            one physics step while paused",
        "  F2           show / hide the developer lines (mode, raw numbers, frame rate)",
        "  F3           show / hide the collision geometry",
        "  F4           carom: the diamond aid, the path to the 3rd cushion",
        "  + / -        sound volume up / down",
        "  U            mute / unmute the sound",
        "  H or F1      show / hide this help",
        "  F11          fullscreen",
        "  Escape       menu: resume, restart, the start menu (M), quit (quit asks first)",
    ];
}
