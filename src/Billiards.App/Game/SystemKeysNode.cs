using Billiards.App.Input;
using Billiards.App.Nodes;
using Billiards.App.Platform;

namespace Billiards.App.Game;

/// <summary>
/// Keys that are not about playing: pause (P), single step (N), help (H or F1), developer lines (F2), debug collision
/// geometry (F3) and fullscreen (F11); Escape opens the menu (<see cref="Hud.MenuNode"/>). Window actions are signals the host connects
/// to the window; pause and step go to the fixed-step loop.
/// </summary>
public sealed class SystemKeysNode(FixedStepLoop loop) : Node
{
    /// <summary>The loop paused and stepped by P and N.</summary>
    public FixedStepLoop Loop { get; } = loop;

    /// <summary>True while the help overlay is open (the start menu's Controls opens it too).</summary>
    public bool ShowHelp { get; set; }

    /// <summary>The key that shows or hides the developer lines (mode, raw numbers, frame rate).</summary>
    public const Key DeveloperKey = Key.F2;

    /// <summary>True while the developer lines are shown beside the scoreboard.</summary>
    public bool ShowDeveloper { get; private set; }

    /// <summary>True while the collision geometry is drawn.</summary>
    public bool ShowCollisionGeometry { get; private set; }

    /// <summary>Signal: F11 was pressed.</summary>
    public event Action? FullscreenRequested;


    /// <inheritdoc />
    protected override bool Input(InputEvent e)
    {
        if (e is not KeyInput { Pressed: true } key)
        {
            return false;
        }
        switch (key.Key)
        {
            case Key.P:
                Loop.TogglePause();
                return true;
            case Key.N:
                // The Key enum has no period key; N is the single-step key.
                Loop.RequestSingleStep();
                return true;
            case Key.H or Key.F1:
                ShowHelp = !ShowHelp;
                return true;
            case DeveloperKey:
                ShowDeveloper = !ShowDeveloper;
                return true;
            case Key.F3:
                ShowCollisionGeometry = !ShowCollisionGeometry;
                return true;
            case Key.F11:
                FullscreenRequested?.Invoke();
                return true;
            default:
                return false;
        }
    }

    /// <inheritdoc />
    protected override void Draw(FrameBuilder frame) => frame.Frame.ShowCollisionGeometry = ShowCollisionGeometry;
}
