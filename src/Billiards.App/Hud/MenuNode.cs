using System.Numerics;
using Billiards.App.Game;
using Billiards.App.Input;
using Billiards.App.Nodes;
using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.Core.Physics;
using Billiards.Core.Rules;

namespace Billiards.App.Hud;

/// <summary>What the menu shows.</summary>
public enum MenuPage
{
    /// <summary>No menu: the game.</summary>
    None,
    /// <summary>The pause menu: resume, restart, the start menu, quit.</summary>
    Pause,
    /// <summary>Quit asks first.</summary>
    ConfirmQuit,
    /// <summary>The start menu's first screen: the title, then Play, Practice, Drills, Settings, Controls and Quit.</summary>
    Start,
    /// <summary>The start menu's Play screen: the game, the opponent, then Start.</summary>
    Play,
    /// <summary>The start menu's drills: a gallery of each drill's picture, title and goal.</summary>
    Drills,
    /// <summary>The start menu's settings: the physics in words, the computer's pace, take-backs, sound.</summary>
    Settings,
    /// <summary>The start menu's "Play online": host a game or join one.</summary>
    Online,
    /// <summary>Hosting: the game to host (the physics are the settings'), then Host.</summary>
    Host,
    /// <summary>Joining: the host's address and the code typed, then Join.</summary>
    Join,
    /// <summary>The hosted game's code and address, while it waits for a player.</summary>
    Hosting,
}

/// <summary>
/// The pause menu (Escape: resume, restart, the start menu, quit; quit asks before it quits), the buttons of
/// the incoming player's options, and at game over Rematch (Enter) and Menu (M) under the result panel. Buttons are laid out here in pixels and hit-tested against the
/// same rectangles the HUD draws; each also has its key (Escape, R, Q, Y, N; 1-5 for the options).
/// While a menu is open the game is paused and takes no other input but the help (H or F1).
/// </summary>
public sealed partial class MenuNode : Node
{
    /// <summary>The key that opens the start menu from the result panel.</summary>
    public const Key MenuKey = Key.M;

    private readonly List<(HudButton Button, Action Act)> _buttons = [];
    private SystemKeysNode? _keys;
    private MatchNode? _match;
    private PhysicsNode? _physics;
    private InstantReplayNode? _replay;
    private bool _wasPaused;
    private (int Width, int Height) _size = (1280, 720);

    /// <summary>The page shown.</summary>
    public MenuPage Page { get; private set; }

    /// <summary>The buttons of the last frame drawn.</summary>
    public IReadOnlyList<HudButton> Buttons => _buttons.Select(b => b.Button).ToList();

    /// <summary>Signal: the player confirmed quitting.</summary>
    public event Action? QuitConfirmed;

    /// <summary>Signal: the start menu's settings were changed and Start pressed (to keep them).</summary>
    public event Action<GameSettings>? SettingsChosen;

    /// <summary>Signal: the start menu asks for a new game of these rules between these players.</summary>
    public event Action<GameRules, Seat[]>? StartRequested;

    /// <summary>Signal: the start menu asks for practice: free (null) or the drill of this name.</summary>
    public event Action<string?>? PracticeRequested;

    /// <summary>The drills the start menu offers: (name, title), set by the host (none by default).</summary>
    public IReadOnlyList<(string Name, string Title)> Drills { get; set; } = [];

    /// <summary>The start menu's game (remembered in the settings).</summary>
    public GameRules StartGame
    {
        get => StartSettings.Game;
        private set => StartSettings = StartSettings with { Game = value };
    }

    /// <summary>The start menu's opponent: a computer level, or null for a person (remembered in the settings).</summary>
    public int? StartOpponent
    {
        get => StartSettings.Opponent;
        private set => StartSettings = StartSettings with { Opponent = value };
    }

    /// <summary>The start menu's physics (cushion model and cloth); the game behind the menu was made with <see cref="PlayedSettings"/>.</summary>
    public GameSettings StartSettings { get; set; } = GameSettings.Default;

    /// <summary>The physics of the game behind the menu.</summary>
    public GameSettings PlayedSettings { get; set; } = GameSettings.Default;

    /// <summary>Opens the start menu at <paramref name="page"/> (its first screen by default), the game paused behind it; the choices shown are the last ones made (the settings file keeps them).</summary>
    public void ShowStart(MenuPage page = MenuPage.Start)
    {
        if (Page == MenuPage.None)
        {
            Open();
        }
        Go(page);
    }

    private void Begin()
    {
        Resume();
        if (_match is not null && _match.Session.Rules == StartGame && _match.Session.Seats[1].ComputerLevel == StartOpponent && _match.Session.Seats[0].IsHuman && StartSettings.Physics == PlayedSettings.Physics)
        {
            // The game behind the menu is the one chosen; a new pace or take-back setting takes effect in it at once.
            if (FindInTree<ComputerPlayerNode>() is { } computer)
            {
                computer.Fast = StartSettings.FastComputer;
            }
            _match.Session.TakeBacks = StartSettings.TakeBacks;
            PlayedSettings = StartSettings;
            SettingsChosen?.Invoke(StartSettings);
            return;
        }
        SettingsChosen?.Invoke(StartSettings);
        // A game the computer does not play seats a person.
        var opponent = StartOpponent is int level && Ruleset.For(StartGame).HasComputerPlayer ? new Seat($"Computer L{level}", level) : new Seat("Player 2");
        StartRequested?.Invoke(StartGame, [new Seat("Player 1"), opponent]);
    }

    /// <inheritdoc />
    protected override void Ready()
    {
        _keys = GetInTree<SystemKeysNode>();
        _match = FindInTree<MatchNode>();
        _physics = GetInTree<PhysicsNode>();
        _replay = FindInTree<InstantReplayNode>();
    }

    /// <inheritdoc />
    protected override bool Input(InputEvent e)
    {
        if (e is MouseButtonInput { Pressed: true, Button: MouseButton.Left } click)
        {
            Layout();
            foreach (var (button, act) in _buttons)
            {
                if (button.Contains(click.Position))
                {
                    act();
                    return true;
                }
            }
            return Page != MenuPage.None;
        }
        if (e is MouseMoveInput move && IsStartScreen)
        {
            // The focus follows the pointer when it moves, not where it happened to rest when the
            // window opened (the first report has no motion): Enter then still plays.
            if (move.Delta != Vector2.Zero)
            {
                Hover(move.Position);
            }
            return true;
        }
        if (e is KeyInput { Pressed: true } key)
        {
            return TypeOnline(key.Key, key.Shift) || OnKey(key.Key);
        }
        // A menu takes every other input while it is open.
        return Page != MenuPage.None;
    }

    private bool OnKey(Key key)
    {
        if (key is Key.H or Key.F1)
        {
            return false; // the help (SystemKeysNode) opens over every page, as the HUD offers
        }
        switch (Page)
        {
            case MenuPage.None when key == Key.Escape && _replay is { IsActive: true }:
                return false; // Escape leaves the instant replay first
            case MenuPage.None when key == Key.Escape:
                Open();
                return true;
            case MenuPage.None when key == MenuKey && _match is { Session.IsOver: true, Session.RematchIn: null }:
                ShowStart();
                return true;
            case MenuPage.None:
                return false;
            case not MenuPage.Pause and not MenuPage.ConfirmQuit when IsStartScreen:
                StartKey(key);
                return true;
            case MenuPage.Pause:
                switch (key)
                {
                    case Key.Escape:
                        Resume();
                        break;
                    case Key.R:
                        Restart();
                        break;
                    case MenuKey when CanLeaveForStart:
                        Go(MenuPage.Start);
                        break;
                    case Key.Q:
                        AskQuit();
                        break;
                }
                return true;
            default:
                switch (key)
                {
                    case Key.Y:
                        QuitConfirmed?.Invoke();
                        break;
                    case Key.N or Key.Escape:
                        Page = _quitReturn;
                        break;
                }
                return true;
        }
    }

    private void Open()
    {
        _wasPaused = _keys!.Loop.Paused;
        _keys.Loop.Paused = true;
        Page = MenuPage.Pause;
    }

    // The pause menu leads to the start menu (another game, practice, settings; Escape there comes
    // back to this game) unless the game is played online: leaving it there would end it for both.
    private bool CanLeaveForStart => _match is not { IsNetworked: true };

    private void Resume()
    {
        Page = MenuPage.None;
        _keys!.Loop.Paused = _wasPaused;
    }

    // Restart asked while the balls roll: done as soon as they rest (the shot is judged first).
    private bool _restartAtRest;

    /// <summary>True while a restart asked for during a shot waits for the balls to rest.</summary>
    public bool RestartPending => _restartAtRest;

    /// <inheritdoc />
    protected override void Process(double dt)
    {
        if (_restartAtRest && Page == MenuPage.None && _physics is { IsRolling: false })
        {
            _restartAtRest = false;
            Restart();
        }
        ProcessOnline();
    }

    private void Restart()
    {
        if (_match is not null && _physics is { IsRolling: true })
        {
            // The match racks only between shots: the menu closes, the shot runs out, then the game restarts.
            _restartAtRest = true;
            Resume();
            return;
        }
        if (_match is not null)
        {
            _match.Restart();
        }
        else if (FindInTree<PracticeNode>() is { } practice)
        {
            practice.Restart();
        }
        else
        {
            _physics?.Restart();
        }
        Resume();
    }

    /// <inheritdoc />
    protected override void Draw(FrameBuilder frame)
    {
        _size = (frame.Frame.Width, frame.Frame.Height);
        string? title = Layout();
        if (frame.Frame.Hud is { } start && IsStartScreen)
        {
            // The start menu is the whole screen: no scoreboard, keys or gauges of the game behind it.
            frame.Frame.Hud = start with
            {
                Lines = [], Icons = null, Aids = null, Power = null, Board = null, Gauges = null, Result = null, Developer = false,
                Buttons = Buttons, Title = null, Labels = _labels.ToArray(), Backdrop = true,
            };
            return;
        }
        if (frame.Frame.Hud is { } hud && _buttons.Count > 0)
        {
            // An open menu hides the result panel it covers.
            frame.Frame.Hud = hud with { Buttons = Buttons, Title = title, Result = Page == MenuPage.None ? hud.Result : null };
        }
    }

    // The buttons of the page (or the options), centred; returns the title.
    private string? Layout()
    {
        _buttons.Clear();
        _labels.Clear();
        if (IsStartScreen)
        {
            LayoutStart();
            return null;
        }
        var (width, height) = _size;
        int scale = HudRenderer.Scale(height);
        float line = HudFont.LineHeight * scale;
        float buttonHeight = line + (8 * scale);
        var rows = new List<List<(string Label, Action Act)>>();
        var items = new List<(string Label, Action Act)>();
        rows.Add(items);
        string? title = null;
        float y;
        switch (Page)
        {
            case MenuPage.Pause:
                title = "Paused";
                items.Add(("Resume [Esc]", Resume));
                items.Add(("Restart [R]", Restart));
                if (CanLeaveForStart)
                {
                    items.Add(($"Menu [{MenuKey}]", () => Go(MenuPage.Start)));
                }
                items.Add(("Quit [Q]", (Action)AskQuit));
                y = height / 2f;
                break;
            case MenuPage.ConfirmQuit:
                title = "Quit the game?";
                items.Add(("Yes, quit [Y]", () => QuitConfirmed?.Invoke()));
                items.Add(("No [N]", () => Page = _quitReturn));
                y = height / 2f;
                break;
            default:
                if (_match is { Session.IsOver: true, Session.RematchIn: null } over)
                {
                    // Under the result panel (HudRenderer draws it above 0.64 of the height).
                    if (!over.IsNetworked)
                    {
                        items.Add(("Rematch [Enter]", () => over.Rematch()));
                    }
                    items.Add(($"Menu [{MenuKey}]", () => ShowStart()));
                    y = height * 0.66f;
                    break;
                }
                // No choice over an instant replay: its buttons would hide the shot replayed.
                if (_match is not { Session.PendingOptions.Count: > 0, IsWatching: false } match || _replay is { IsActive: true })
                {
                    return null;
                }
                title = $"{match.Session.State.ShooterName} chooses:";
                for (int i = 0; i < match.Session.PendingOptions.Count; i++)
                {
                    var option = match.Session.PendingOptions[i];
                    items.Add(($"{option.ToName()} [{i + 1}]", () => match.Choose(option)));
                }
                // Low in the view, clear of the table's middle.
                y = height * 0.78f;
                break;
        }
        float gap = 6 * scale;
        foreach (var row in rows)
        {
            float buttonWidth = (row.Max(i => HudFont.Width(i.Label)) * scale) + (16 * scale);
            float total = (row.Count * buttonWidth) + ((row.Count - 1) * gap);
            float x = (width - total) / 2;
            foreach (var (label, act) in row)
            {
                _buttons.Add((new HudButton(x, y, buttonWidth, buttonHeight, label), act));
                x += buttonWidth + gap;
            }
            y += buttonHeight + gap;
        }
        return title;
    }

    private void RequestPractice(string? drill)
    {
        Resume();
        PracticeRequested?.Invoke(drill);
    }

    /// <summary>Presses the button whose label starts with <paramref name="label"/> (tests and scripts use clicks; this is the same action).</summary>
    public Vector2? CentreOf(string label)
    {
        Layout();
        foreach (var (b, _) in _buttons)
        {
            if (b.Label.StartsWith(label, StringComparison.Ordinal))
            {
                return new Vector2(b.X + (b.Width / 2), b.Y + (b.Height / 2));
            }
        }
        return null;
    }
}
