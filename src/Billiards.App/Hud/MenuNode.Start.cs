using System.Numerics;
using Billiards.App.Audio;
using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.Core.Balls;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Collisions;
using Billiards.Core.Practice;
using Billiards.Core.Rules;

namespace Billiards.App.Hud;

// The start menu's screens. Each screen is laid out from the window's size alone, every button of a
// row as wide as the row's widest label could be, and a choice is marked by colour, not by a
// label's text: nothing moves under the pointer when a choice changes. The keyboard moves a focus
// (arrows, Tab), Enter presses it and Escape goes back; the mouse's pointer moves the same focus.
public sealed partial class MenuNode
{
    private readonly List<HudLabel> _labels = [];
    private readonly List<int> _rowOf = [];

    // The group of each button: the buttons one row of choices laid out (the games, wrapped into
    // lines or not; the opponents; Start and Back; the drills' grid), within which Left and Right move.
    private readonly List<int> _groupOf = [];
    private int _focus;
    private MenuPage _quitReturn = MenuPage.Pause;

    /// <summary>The game's name on the start menu.</summary>
    public const string GameTitle = "Billiards";

    /// <summary>True while one of the start menu's screens is shown.</summary>
    public bool IsStartScreen => Page is MenuPage.Start or MenuPage.Play or MenuPage.Drills or MenuPage.Settings || IsOnlinePage(Page);

    /// <summary>The drills the start menu's gallery shows, with their pictures and goals; set by the host (none by default).</summary>
    public IReadOnlyList<Drill> DrillGallery { get; set; } = [];

    /// <summary>The text of the focused button, or null (tests read the keyboard's focus through it).</summary>
    public string? FocusedLabel
    {
        get
        {
            Layout();
            return _focus >= 0 && _focus < _buttons.Count ? _buttons[_focus].Button.Label : null;
        }
    }

    /// <summary>A game's name as the menu says it.</summary>
    public static string GameName(GameRules game) => game.ToName() switch
    {
        "eight-ball" => "8-ball",
        "nine-ball" => "9-ball",
        "ten-ball" => "10-ball",
        "straight-pool" => "14.1 straight pool",
        "snooker" => "Snooker",
        "three-cushion" => "Three-cushion",
        var other => other,
    };

    /// <summary>A cushion model in words, its paper in brackets.</summary>
    public static string CushionName(IBallCushionModel model)
    {
        ArgumentNullException.ThrowIfNull(model);
        return model.Name switch
        {
            "han-2005" => "standard (Han 2005)",
            "mathavan-2010" => "precise, slower (Mathavan 2010)",
            "stronge-compliant" => "soft rubber (Stronge, compliant)",
            var other => other,
        };
    }

    /// <summary>A cloth in words.</summary>
    public static string ClothName(Cloth cloth)
    {
        ArgumentNullException.ThrowIfNull(cloth);
        return cloth.Name switch
        {
            "slow" => "slow (heavy cloth)",
            "standard" => "standard",
            "fast" => "fast (tournament cloth)",
            var other => other,
        };
    }

    private void Go(MenuPage page)
    {
        Page = page;
        _focus = 0;
        if (page is MenuPage.Play or MenuPage.Host)
        {
            _focus = -1; // Start, found by the layout
        }
    }

    private void AskQuit()
    {
        _quitReturn = Page == MenuPage.Pause ? MenuPage.Pause : Page;
        Page = MenuPage.ConfirmQuit;
    }

    private void StartKey(Key key)
    {
        Layout();
        if (_keys is { ShowHelp: true } && key == Key.Escape)
        {
            _keys.ShowHelp = false; // the Controls screen is the help overlay: Escape closes it
            return;
        }
        switch (key)
        {
            case Key.Escape when Page == MenuPage.Start:
                Resume(); // back to the game behind the menu
                break;
            case Key.Escape or Key.Backspace:
                Back();
                break;
            case Key.Enter or Key.Space:
                if (_focus >= 0 && _focus < _buttons.Count)
                {
                    _buttons[_focus].Act();
                }
                break;
            case Key.Tab:
                _focus = Math.Clamp(_focus + 1, 0, _buttons.Count - 1);
                break;
            case Key.Left or Key.Right:
                // Within the focused row of choices (from the opponents, Left does not jump back to
                // the games); a button alone in its row stays.
                int next = _focus + (key == Key.Left ? -1 : 1);
                if (_focus >= 0 && _focus < _buttons.Count && next >= 0 && next < _buttons.Count && _groupOf[next] == _groupOf[_focus])
                {
                    _focus = next;
                }
                break;
            case Key.Up or Key.Down:
                _focus = NextRow(key == Key.Up ? -1 : 1);
                break;
        }
    }

    // The button of the row above or below nearest the focus's centre.
    private int NextRow(int direction)
    {
        if (_buttons.Count == 0)
        {
            return 0;
        }
        int from = Math.Clamp(_focus, 0, _buttons.Count - 1);
        int row = _rowOf[from] + direction;
        float x = _buttons[from].Button.X + (_buttons[from].Button.Width / 2);
        int best = from;
        float bestDistance = float.MaxValue;
        for (int i = 0; i < _buttons.Count; i++)
        {
            if (_rowOf[i] != row)
            {
                continue;
            }
            float d = MathF.Abs(_buttons[i].Button.X + (_buttons[i].Button.Width / 2) - x);
            if (d < bestDistance)
            {
                bestDistance = d;
                best = i;
            }
        }
        return best;
    }

    private void Hover(Vector2 at)
    {
        Layout();
        for (int i = 0; i < _buttons.Count; i++)
        {
            if (_buttons[i].Button.Contains(at))
            {
                _focus = i;
                return;
            }
        }
    }

    private void Back()
    {
        if (Page == MenuPage.Settings)
        {
            ApplySettings();
        }
        Go(IsOnlinePage(Page) ? OnlineBack() : MenuPage.Start);
    }

    // The settings take effect on leaving their screen: the file keeps them, the game behind the menu
    // takes the pace, take-backs, sound and graphics at once; the physics makes the next game started.
    private void ApplySettings()
    {
        SettingsChosen?.Invoke(StartSettings);
        if (FindInTree<ComputerPlayerNode>() is { } computer)
        {
            computer.Fast = StartSettings.FastComputer;
        }
        if (_match is not null)
        {
            _match.Session.TakeBacks = StartSettings.TakeBacks;
        }
        if (FindInTree<AudioNode>() is { } audio)
        {
            audio.Output.Muted = StartSettings.Muted;
        }
        PlayedSettings = PlayedSettings with { FastComputer = StartSettings.FastComputer, TakeBacks = StartSettings.TakeBacks, Muted = StartSettings.Muted, Graphics = StartSettings.Graphics };
    }

    /// <summary>
    /// Lays out a row of buttons of one width, centred, at <c>y</c>: in as few lines as the window's
    /// width holds, each of about as many buttons; returns the height it took beyond one line.
    /// </summary>
    private delegate float ButtonRow(float y, float w, IReadOnlyList<(string Label, Action Act, bool Chosen)> items);

    // The games to choose from, under their label, the one chosen marked; returns the y below.
    private float GameRow(float y, float line, float u, float cx, ButtonRow row)
    {
        var games = Ruleset.All.Select(r => r.Game).ToList();
        float gameW = (games.Max(g => HudFont.Width(GameName(g))) + 16) * u;
        _labels.Add(new HudLabel(cx, y, "Game", 1, Gold: true, Centred: true));
        y += line + (2 * u);
        float more = row(y, gameW, [.. games.Select(g => (GameName(g), (Action)(() => StartGame = g), StartGame == g))]);
        return y + more + line + (10 * u) + (2 * line);
    }

    private void NextCushion() => StartSettings = StartSettings with { Cushion = Cycle(ModelRegistry.BallCushionModels, StartSettings.Cushion) };

    private void NextCloth() => StartSettings = StartSettings with { Cloth = Cycle(Cloth.All, StartSettings.Cloth) };

    private static T Cycle<T>(IReadOnlyList<T> all, T current) where T : class
    {
        int i = 0;
        for (; i < all.Count && !ReferenceEquals(all[i], current) && !Equals(all[i], current); i++)
        {
        }
        return all[(i + 1) % all.Count];
    }

    /// <summary>
    /// The gallery's grid in <paramref name="width"/> by <paramref name="room"/> pixels: the largest
    /// title, then the largest goal (the title's scale or one less), then the fewest columns (at
    /// least four), whose cards hold every drill's title (no word broken between letters) and goal;
    /// where none fits, the smallest text in the grid that overflows least.
    /// </summary>
    internal static (int Columns, float CardWidth, float CardHeight, int TextScale, int NoteScale) Gallery(IReadOnlyList<Drill> drills, float width, float room, float gap, int scale)
    {
        (int, float, float, int, int)? best = null;
        float bestHeight = float.MaxValue;
        for (int textScale = scale; textScale >= 1; textScale--)
        {
            for (int noteScale = textScale; noteScale >= Math.Max(1, textScale - 1); noteScale--)
            {
                for (int columns = Math.Min(4, Math.Max(1, drills.Count)); columns <= Math.Max(4, drills.Count); columns++)
                {
                    float cardW = MathF.Min(150 * textScale, (width - ((columns + 1) * gap)) / columns);
                    float cardH = drills.Select(d => CardLayout.Height(d.Title, d.Goal, cardW, textScale, noteScale)).DefaultIfEmpty(0).Max();
                    int rows = Math.Max(1, (drills.Count + columns - 1) / columns);
                    float needed = rows * (cardH + gap);
                    if (needed <= room && drills.All(d => CardLayout.TitleWordsFit(d.Title, cardW, textScale)))
                    {
                        return (columns, cardW, cardH, textScale, noteScale);
                    }
                    if (textScale == 1 && needed < bestHeight)
                    {
                        bestHeight = needed;
                        best = (columns, cardW, cardH, textScale, noteScale);
                    }
                }
            }
        }
        return best ?? (4, 150, 150, 1, 1);
    }

    // The last grid Gallery chose and what it was chosen for: the menu lays out every frame, the
    // search measures every drill's text in many grids, and only a new window size or gallery changes it.
    private (IReadOnlyList<Drill> Drills, float Width, float Room, float Gap, int Scale, (int, float, float, int, int) Grid)? _gallery;

    private (int Columns, float CardWidth, float CardHeight, int TextScale, int NoteScale) GalleryGrid(float width, float room, float gap, int scale)
    {
        if (_gallery is not { } g || !ReferenceEquals(g.Drills, DrillGallery) || g.Width != width || g.Room != room || g.Gap != gap || g.Scale != scale)
        {
            g = (DrillGallery, width, room, gap, scale, Gallery(DrillGallery, width, room, gap, scale));
            _gallery = g;
        }
        return g.Grid;
    }

    private void LayoutStart()
    {
        var (width, height) = _size;
        int scale = HudRenderer.Scale(height);
        float u = scale, line = HudFont.LineHeight * u;
        float buttonH = line + (10 * u), gap = 6 * u;
        float cx = width / 2f;
        _rowOf.Clear();
        _groupOf.Clear();
        int row = 0, group = 0;
        void Add(float x, float y, float w, float h, string label, Action act, bool chosen = false, string? note = null, HudPicture? picture = null, int? textScale = null, int? noteScale = null)
        {
            _buttons.Add((new HudButton(x, y, w, h, label) { Chosen = chosen, Note = note, Picture = picture, TextScale = textScale, NoteScale = noteScale }, act));
            _rowOf.Add(row);
            _groupOf.Add(group);
        }
        // Items of one size in lines of perLine (at least one line), each line centred; add places
        // item k at x, y. Returns the y below the last line.
        float Lines(float y, float w, float h, int count, int perLine, Action<int, float, float> add)
        {
            int start = 0;
            do
            {
                int inLine = Math.Min(perLine, count - start);
                float x = cx - (((inLine * w) + ((inLine - 1) * gap)) / 2);
                for (int k = start; k < start + inLine; k++, x += w + gap)
                {
                    add(k, x, y);
                }
                row++;
                y += h + gap;
                start += perLine;
            }
            while (start < count);
            group++;
            return y;
        }
        // A row of buttons of one width, centred; wrapped into lines of about equal count when
        // the window is too narrow for it (six games in two lines of three, not one cut off).
        float Row(float y, float w, IReadOnlyList<(string Label, Action Act, bool Chosen)> items)
        {
            float room = width - (2 * gap);
            int fit = Math.Clamp((int)((room + gap) / (w + gap)), 1, Math.Max(1, items.Count));
            int lines = Math.Max(1, (items.Count + fit - 1) / fit);
            int perLine = (items.Count + lines - 1) / lines;
            Lines(y, w, buttonH, items.Count, perLine, (k, x, ky) => Add(x, ky, w, buttonH, items[k].Label, items[k].Act, items[k].Chosen));
            return (lines - 1) * (buttonH + gap);
        }
        float top = MathF.Max(line, height * 0.08f);
        _labels.Add(new HudLabel(cx, top, GameTitle, 3, Gold: true, Centred: true));
        float y = top + (3 * line) + (2 * u);
        string subtitle = Page switch
        {
            MenuPage.Play => "Play: choose the game and your opponent, then Start",
            MenuPage.Drills => "Drills: one shot to master, its goal under its picture",
            MenuPage.Settings => "Settings: click a line to change it; Back keeps them",
            _ when IsOnlinePage(Page) => OnlineSubtitle(Page),
            _ => "Pool, snooker and three-cushion",
        };
        _labels.Add(new HudLabel(cx, y, subtitle, 1, Centred: true));
        y += 2 * line;
        float wide = 150 * u;
        switch (Page)
        {
            case MenuPage.Start:
                foreach (var (label, act) in new (string, Action)[]
                {
                    ("Play", () => Go(MenuPage.Play)),
                    ("Play online", () => Go(MenuPage.Online)),
                    ("Practice", () => RequestPractice(null)),
                    ("Drills", () => Go(MenuPage.Drills)),
                    ("Settings", () => Go(MenuPage.Settings)),
                    ("Controls", () => _keys!.ShowHelp = true),
                    ("Quit", AskQuit),
                })
                {
                    Row(y, wide, [(label, act, false)]);
                    y += buttonH + gap;
                }
                _labels.Add(new HudLabel(cx, y + line, "Arrows and Enter, or the mouse;  Esc: back to the table;  H: help", 1, Centred: true));
                break;
            case MenuPage.Play:
            {
                y = GameRow(y, line, u, cx, Row);
                _labels.Add(new HudLabel(cx, y, "Opponent: a second player at this computer, or the computer (level 1 easy, 5 strong)", 1, Gold: true, Centred: true));
                y += line + (2 * u);
                var opponents = new List<(string, Action, bool)> { ("Person", () => StartOpponent = null, StartOpponent is null) };
                for (int level = 1; level <= 5; level++)
                {
                    int l = level;
                    opponents.Add(($"Computer {l}", () => StartOpponent = l, StartOpponent == l));
                }
                y += Row(y, (HudFont.Width("Computer 5") + 16) * u, opponents);
                y += buttonH + (2 * line);
                float startAt = _buttons.Count;
                Row(y, wide, [("Start", Begin, false), ("Back", Back, false)]);
                if (_focus < 0)
                {
                    _focus = (int)startAt;
                }
                break;
            }
            case MenuPage.Drills:
            {
                // A gallery of cards, each the drill's position from above, its title and its goal,
                // every word inside its card: as large a text and as few columns as the window holds.
                var (columns, cardW, cardH, textScale, noteScale) = GalleryGrid(width, height - y - buttonH - (2 * gap), gap, scale);
                y = Lines(y, cardW, cardH, DrillGallery.Count, columns, (k, x, ky) =>
                {
                    var drill = DrillGallery[k];
                    Add(x, ky, cardW, cardH, drill.Title, () => RequestPractice(drill.Name), note: drill.Goal, picture: PictureOf(drill), textScale: textScale, noteScale: noteScale);
                });
                Row(y, wide, [("Back", Back, false)]);
                break;
            }
            case MenuPage.Settings:
            {
                float w = 260 * u;
                var s = StartSettings;
                var items = new (string, Action)[]
                {
                    ($"Cushion: {CushionName(s.Cushion)}", NextCushion),
                    ($"Cloth: {ClothName(s.Cloth)}", NextCloth),
                    ($"Computer's pace: {(s.FastComputer ? "fast" : "watchable")}", () => StartSettings = StartSettings with { FastComputer = !StartSettings.FastComputer }),
                    ($"Take-backs: {(s.TakeBacks ? "allowed (Z)" : "off")}", () => StartSettings = StartSettings with { TakeBacks = !StartSettings.TakeBacks }),
                    ($"Sound: {(s.Muted ? "muted" : "on")}", () => StartSettings = StartSettings with { Muted = !StartSettings.Muted }),
                    ($"Graphics: {GraphicsWords.Words(s.Graphics)}", () => StartSettings = StartSettings with { Graphics = (GraphicsQuality)(((int)StartSettings.Graphics + 1) % 3) }),
                };
                foreach (var (label, act) in items)
                {
                    Row(y, w, [(label, act, false)]);
                    y += buttonH + gap;
                }
                _labels.Add(new HudLabel(cx, y, "The cushion and the cloth make the next game started; the rest changes at once.", 1, Centred: true));
                y += line + gap;
                Row(y, wide, [("Back", Back, false)]);
                break;
            }
            default:
                LayoutOnline(ref y, wide, line, u, cx, Row);
                break;
        }
        if (_buttons.Count > 0)
        {
            _focus = Math.Clamp(_focus, 0, _buttons.Count - 1);
            var (b, a) = _buttons[_focus];
            _buttons[_focus] = (b with { Focused = true }, a);
        }
    }

    /// <summary>A drill's position from above: its table, its balls, its pockets (the ones to play first).</summary>
    public static HudPicture PictureOf(Drill drill)
    {
        ArgumentNullException.ThrowIfNull(drill);
        var table = drill.Scene.Table;
        var pockets = new List<Vector2>();
        var targets = drill.Pockets.Where(p => p != Billiards.Core.Table.PocketId.None).Select(p => p.Index).ToHashSet();
        var order = Enumerable.Range(0, table.Pockets.Count).OrderBy(i => targets.Contains(i) ? 0 : 1).ToList();
        foreach (int i in order)
        {
            var m = table.Pockets[i].MouthMiddle(table);
            pockets.Add(new Vector2((float)m.X, (float)m.Y));
        }
        // The picture draws pool's colours by number: carom's object balls as the pool ball of their colour.
        static int Number(BallId id) => id == BallSet.Yellow ? 1 : id == BallSet.Red ? 3 : id.Value;
        var balls = drill.Scene.Balls.Select(b => (new Vector2((float)b.Position.X, (float)b.Position.Y), b.Id == drill.Scene.CueBall ? 0 : Number(b.Id))).ToList();
        return new HudPicture((float)table.HalfLength, (float)table.HalfWidth, balls, pockets, targets.Count);
    }
}
