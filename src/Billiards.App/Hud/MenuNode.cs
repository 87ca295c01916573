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
    /// <summary>The pause menu: resume, restart, quit.</summary>
    Pause,
    /// <summary>Quit asks first.</summary>
    ConfirmQuit,
    /// <summary>The start menu: the game and the opponent.</summary>
    Start,
}

/// <summary>
/// The pause menu (Escape: resume, restart, quit; quit asks before it quits), the buttons of
/// the incoming player's options, and at game over Rematch (Enter) and Menu (M) under the result panel. Buttons are laid out here in pixels and hit-tested against the
/// same rectangles the HUD draws; each also has its key (Escape, R, Q, Y, N; 1-5 for the options).
/// While a menu is open the game is paused and takes no other input but the help (H or F1).
/// </summary>
public sealed class MenuNode : Node
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

    /// <summary>The start menu's game.</summary>
    public GameRules StartGame { get; private set; } = GameRules.EightBall;

    /// <summary>The start menu's opponent: a computer level, or null for a person.</summary>
    public int? StartOpponent { get; private set; } = 3;

    /// <summary>The start menu's physics (cushion model and cloth); the game behind the menu was made with <see cref="PlayedSettings"/>.</summary>
    public GameSettings StartSettings { get; set; } = GameSettings.Default;

    /// <summary>The physics of the game behind the menu.</summary>
    public GameSettings PlayedSettings { get; set; } = GameSettings.Default;

    /// <summary>Opens the start menu (the game paused behind it).</summary>
    public void ShowStart()
    {
        if (_match is not null)
        {
            StartGame = _match.Session.Rules;
            StartOpponent = _match.Players[1].ComputerLevel;
        }
        Open();
        Page = MenuPage.Start;
    }

    private void Begin()
    {
        Resume();
        if (StartSettings != PlayedSettings)
        {
            SettingsChosen?.Invoke(StartSettings);
        }
        if (_match is not null && _match.Session.Rules == StartGame && _match.Players[1].ComputerLevel == StartOpponent && _match.Players[0].IsHuman && StartSettings.Physics == PlayedSettings.Physics)
        {
            // The game behind the menu is the one chosen; a new pace or take-back setting takes effect in it at once.
            if (FindInTree<ComputerPlayerNode>() is { } computer)
            {
                computer.Fast = StartSettings.FastComputer;
            }
            _match.TakeBacks = StartSettings.TakeBacks;
            PlayedSettings = StartSettings;
            return;
        }
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
        if (e is KeyInput { Pressed: true } key)
        {
            return OnKey(key.Key);
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
            case MenuPage.None when key == MenuKey && _match is { IsOver: true, Session.RematchIn: null }:
                ShowStart();
                return true;
            case MenuPage.None:
                return false;
            case MenuPage.Start:
                if (key is Key.Enter or Key.Escape)
                {
                    Begin();
                }
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
                    case Key.Q:
                        Page = MenuPage.ConfirmQuit;
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
                        Page = MenuPage.Pause;
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

    private void Resume()
    {
        Page = MenuPage.None;
        _keys!.Loop.Paused = _wasPaused;
    }

    private void Restart()
    {
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
            case MenuPage.Start:
                title = Drills.Count > 0
                    ? "New game: game, opponent, physics, pace, take-backs, Start; or practice, a drill"
                    : "New game: the game, the opponent, the physics, the computer's pace, take-backs";
                foreach (var game in Ruleset.All.Select(r => r.Game))
                {
                    items.Add((Mark(game.ToName(), StartGame == game), () => StartGame = game));
                }
                var opponents = new List<(string Label, Action Act)> { (Mark("person", StartOpponent is null), () => StartOpponent = null) };
                for (int level = 1; level <= 5; level++)
                {
                    int l = level;
                    opponents.Add((Mark($"level {l}", StartOpponent == l), () => StartOpponent = l));
                }
                rows.Add(opponents);
                rows.Add([.. ModelRegistry.BallCushionModels.Select(m => (Mark($"Physics: {m.Name}", StartSettings.Cushion == m), (Action)(() => StartSettings = StartSettings with { Cushion = m })))]);
                rows.Add([.. Cloth.All.Select(c => (Mark($"{c.Name} cloth", StartSettings.Cloth == c), (Action)(() => StartSettings = StartSettings with { Cloth = c })))]);
                // The computer's pace and take-backs beside Start, each one button that switches it (a
                // row of their own would push the drills off a 720-line window).
                rows.Add([("Start [Enter]", Begin),
                    (StartSettings.FastComputer ? "computer: fast" : "computer: watchable", () => StartSettings = StartSettings with { FastComputer = !StartSettings.FastComputer }),
                    (StartSettings.TakeBacks ? "take-backs: allowed (Z)" : "take-backs: off", () => StartSettings = StartSettings with { TakeBacks = !StartSettings.TakeBacks })]);
                rows.Add([("Practice (no referee)", () => RequestPractice(null))]);
                // The drills by their titles, four to a row so that the rows fit a small window.
                for (int i = 0; i < Drills.Count; i += 4)
                {
                    rows.Add([.. Drills.Skip(i).Take(4).Select(d => (Label: d.Title, Act: (Action)(() => RequestPractice(d.Name))))]);
                }
                // Below the HUD panel, whose lines reach about 0.4 of the height at the start.
                y = height * (Drills.Count > 0 ? 0.4f : 0.5f);
                break;
            case MenuPage.Pause:
                title = "Paused";
                items.Add(("Resume [Esc]", Resume));
                items.Add(("Restart [R]", Restart));
                items.Add(("Quit [Q]", () => Page = MenuPage.ConfirmQuit));
                y = height / 2f;
                break;
            case MenuPage.ConfirmQuit:
                title = "Quit the game?";
                items.Add(("Yes, quit [Y]", () => QuitConfirmed?.Invoke()));
                items.Add(("No [N]", () => Page = MenuPage.Pause));
                y = height / 2f;
                break;
            default:
                if (_match is { IsOver: true, Session.RematchIn: null } over)
                {
                    // Under the result panel (HudRenderer draws it above 0.64 of the height).
                    items.Add(("Rematch [Enter]", over.Rematch));
                    items.Add(($"Menu [{MenuKey}]", ShowStart));
                    y = height * 0.66f;
                    break;
                }
                if (_match is not { PendingOptions.Count: > 0, IsComputerActing: false } match)
                {
                    return null;
                }
                title = $"{match.State.ShooterName} chooses:";
                for (int i = 0; i < match.PendingOptions.Count; i++)
                {
                    var option = match.PendingOptions[i];
                    items.Add(($"{option.ToName()} [{i + 1}]", () => match.Choose(option)));
                }
                // Low in the view, clear of the table's middle.
                y = height * 0.78f;
                break;
        }
        float gap = 6 * scale;
        foreach (var row in rows)
        {
            float buttonWidth = (row.Max(i => i.Label.Length) * HudFont.Advance * scale) + (16 * scale);
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

    private static string Mark(string label, bool chosen) => chosen ? $"> {label} <" : label;

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
