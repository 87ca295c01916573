using Billiards.App.Hud;
using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.App.Tests.Game;

namespace Billiards.App.Tests.Hud;

/// <summary>
/// Every page of the start menu fits the window at the sizes a player gives it: each button lies
/// whole inside the window, no two overlap, its label fits it, and Up and Down reach every row.
/// A row too wide for a narrow window (the six games at 1000 px) wraps into lines, not off-screen.
/// </summary>
public sealed class MenuLayoutTests
{
    public static TheoryData<MenuPage, int, int> PagesAndSizes()
    {
        var data = new TheoryData<MenuPage, int, int>();
        foreach (var page in new[] { MenuPage.Start, MenuPage.Play, MenuPage.Drills, MenuPage.Settings, MenuPage.Online, MenuPage.Host, MenuPage.Join })
        {
            foreach (var (w, h) in new[] { (1280, 720), (1000, 760), (900, 720), (900, 560), (800, 600) })
            {
                data.Add(page, w, h);
            }
        }
        return data;
    }

    [Theory]
    [MemberData(nameof(PagesAndSizes))]
    public void EveryButtonLiesInsideTheWindowAndNoneOverlap(MenuPage page, int width, int height)
    {
        using var game = new TestGame();
        game.Window.FramebufferSize = (width, height);
        game.World.Menu.DrillGallery = Billiards.App.Practice.DrillLibrary.All();
        game.World.Menu.ShowStart(page);
        game.Frame();
        var buttons = game.Frame().Hud!.Buttons!;
        Assert.NotEmpty(buttons);
        float u = HudRenderer.Scale(height);
        foreach (var b in buttons)
        {
            Assert.True(b.X >= 0 && b.Y >= 0 && b.X + b.Width <= width && b.Y + b.Height <= height,
                $"{page} at {width}x{height}: \"{b.Label}\" at ({b.X}, {b.Y}) {b.Width}x{b.Height} is not inside the window");
            if (page != MenuPage.Drills)
            {
                // A drill's card shows its title in a smaller line under its picture.
                Assert.True(HudFont.Width(b.Label) * u <= b.Width, $"{page} at {width}x{height}: \"{b.Label}\" is wider than its button");
            }
        }
        for (int i = 0; i < buttons.Count; i++)
        {
            for (int j = i + 1; j < buttons.Count; j++)
            {
                Assert.False(Overlap(buttons[i], buttons[j]), $"{page} at {width}x{height}: \"{buttons[i].Label}\" and \"{buttons[j].Label}\" overlap");
            }
        }
    }

    // The game buttons: every button above the opponents' row (other tests of the process may
    // register games of their own, so the games are not counted from a fixed list).
    private static List<HudButton> GameButtons(IReadOnlyList<HudButton> buttons)
    {
        float opponents = buttons.Single(b => b.Label == "Person").Y;
        return [.. buttons.Where(b => b.Y < opponents)];
    }

    // Left and Right move within the focused row of choices: through the games across their lines
    // (the end of one line to the start of the next), never from the opponents back into the games
    // or from the games on to the opponents; a button alone in its row (the start page's) stays.
    [Fact]
    public void LeftAndRightMoveWithinTheFocusedRowOfChoices()
    {
        using var game = new TestGame();
        game.Window.FramebufferSize = (1000, 760);
        var menu = game.World.Menu;
        menu.ShowStart();
        game.Frame();
        Assert.Equal("Play", menu.FocusedLabel);
        game.Window.Press(Key.Right);
        game.Window.Press(Key.Left);
        game.Frame();
        Assert.Equal("Play", menu.FocusedLabel);
        menu.ShowStart(MenuPage.Play);
        var games = GameButtons(game.Frame().Hud!.Buttons!);
        var lines = games.GroupBy(b => b.Y).OrderBy(g => g.Key).Select(g => g.Select(b => b.Label).ToList()).ToList();
        Assert.True(lines.Count >= 2, "the games are on one line at 1000 px");
        void Press(Key key, int times = 1)
        {
            for (int i = 0; i < times; i++)
            {
                game.Window.Press(key);
                game.Frame();
            }
        }
        // From Start up to the opponents; Left as often as there are buttons: Person, not a game.
        Press(Key.Up);
        Press(Key.Left, game.Frame().Hud!.Buttons!.Count);
        Assert.Equal("Person", menu.FocusedLabel);
        // Up to the games' last line, Left through the lines to the first game; Right to the next
        // line's first, Left back to the end of the line above.
        Press(Key.Up);
        Press(Key.Left, games.Count);
        Assert.Equal(games[0].Label, menu.FocusedLabel);
        Press(Key.Right, lines[0].Count);
        Assert.Equal(lines[1][0], menu.FocusedLabel);
        Press(Key.Left);
        Assert.Equal(lines[0][^1], menu.FocusedLabel);
        // Right past the last game stays on it.
        Press(Key.Right, games.Count + 3);
        Assert.Equal(games[^1].Label, menu.FocusedLabel);
    }

    [Fact]
    public void TheGamesWrapIntoLinesOfAboutEqualCountInANarrowWindowAndTheKeysReachEachLine()
    {
        using var game = new TestGame();
        game.Window.FramebufferSize = (1000, 760);
        var menu = game.World.Menu;
        menu.ShowStart(MenuPage.Play);
        game.Frame();
        var games = GameButtons(game.Frame().Hud!.Buttons!);
        Assert.Equal(Billiards.Core.Rules.Ruleset.All.Count, games.Count);
        Assert.Contains(games, b => b.Label == "Three-cushion");
        var lines = games.GroupBy(b => b.Y).OrderBy(g => g.Key).Select(g => g.Select(b => b.Label).ToList()).ToList();
        // The six shipped games at 1000 px: two lines of three.
        Assert.Equal(2, lines.Count);
        Assert.True(lines[0].Count - lines[1].Count is 0 or 1, $"lines of {lines[0].Count} and {lines[1].Count}");
        // From Start, Up goes to the opponents, then to the second line of games, then to the first:
        // Enter there picks a game of the first line, Down and Enter one of the second.
        foreach (var _ in Enumerable.Range(0, 3))
        {
            game.Window.Press(Key.Up);
        }
        game.Window.Press(Key.Enter);
        string Chosen() => Assert.Single(game.Frame().Hud!.Buttons!, b => b.Chosen && games.Any(g => g.Label == b.Label)).Label;
        Assert.Contains(Chosen(), lines[0]);
        game.Window.Press(Key.Down);
        game.Window.Press(Key.Enter);
        Assert.Contains(Chosen(), lines[1]);
        game.Window.Press(Key.Up);
        game.Window.Press(Key.Enter);
        Assert.Contains(Chosen(), lines[0]);
        // And a window wide enough keeps them on one line.
        game.Window.FramebufferSize = (1280, 720);
        game.Frame();
        games = GameButtons(game.Frame().Hud!.Buttons!);
        float gap = 6 * HudRenderer.Scale(720);
        if ((games.Count * (games[0].Width + gap)) - gap <= 1280 - (2 * gap))
        {
            Assert.Single(games.Select(b => b.Y).Distinct());
        }
    }

    [Theory]
    [InlineData(1280, 720, 2)]
    [InlineData(1000, 760, 2)]
    [InlineData(900, 720, 1)]
    [InlineData(900, 560, 1)]
    [InlineData(800, 600, 1)]
    [InlineData(1920, 1080, 3)]
    public void EveryDrillsTitleAndGoalLieInsideItsCard(int width, int height, int titleScale)
    {
        using var game = new TestGame();
        game.Window.FramebufferSize = (width, height);
        game.World.Menu.DrillGallery = Billiards.App.Practice.DrillLibrary.All();
        game.World.Menu.ShowStart(MenuPage.Drills);
        game.Frame();
        var cards = game.Frame().Hud!.Buttons!.Where(b => b.Picture is not null).ToList();
        Assert.Equal(game.World.Menu.DrillGallery.Count, cards.Count);
        Assert.True(cards.Count >= 17, $"{cards.Count} drills");
        foreach (var card in cards)
        {
            int scale = Assert.IsType<int>(card.TextScale);
            int noteScale = Assert.IsType<int>(card.NoteScale);
            Assert.Equal(titleScale, scale);
            Assert.InRange(noteScale, Math.Max(1, scale - 1), scale);
            float needed = CardLayout.Height(card.Label, card.Note, card.Width, scale, noteScale);
            Assert.True(needed <= card.Height + 0.01f, $"{width}x{height}: \"{card.Label}\" needs {needed} px, its card is {card.Height}");
            Assert.True(CardLayout.TitleWordsFit(card.Label, card.Width, scale), $"{width}x{height}: a word of \"{card.Label}\" is broken");
            // Every word of the goal is drawn.
            var lines = CardLayout.Text(card.Label, card.Note, card.Width, scale, noteScale);
            Assert.Equal(card.Label.Replace(" ", "", StringComparison.Ordinal), string.Concat(lines.Title).Replace(" ", "", StringComparison.Ordinal));
            Assert.Equal(card.Note!.Split(' ', StringSplitOptions.RemoveEmptyEntries), lines.Note.SelectMany(l => l.Split(' ', StringSplitOptions.RemoveEmptyEntries)));
        }
    }

    [Fact]
    public void ACardsTitleBreaksAfterAHyphenNeverBetweenLetters()
    {
        const int Scale = 2;
        float width = (HudFont.Width("Long-short-") * Scale) + (2 * CardLayout.Pad(Scale)) + 1;
        var lines = CardLayout.Text("Long-short-long", null, width, Scale, Scale);
        Assert.Equal(["Long-short-", "long"], lines.Title);
        Assert.True(CardLayout.TitleWordsFit("Long-short-long", width, Scale));
        // Narrower than "Long-short-", wider than each part: a part to a line.
        float narrow = (HudFont.Width("short-") * Scale) + (2 * CardLayout.Pad(Scale)) + 1;
        Assert.Equal(["Long-", "short-", "long"], CardLayout.Text("Long-short-long", null, narrow, Scale, Scale).Title);
        // A word without a hyphen too wide for the card does not fit (the gallery then picks another grid).
        Assert.False(CardLayout.TitleWordsFit("Umbrella", (HudFont.Width("Umbr") * Scale) + (2 * CardLayout.Pad(Scale)), Scale));
        Assert.Equal(["Side pocket", "hold"], CardLayout.Text("Side pocket hold", null, (HudFont.Width("Side pocket") * Scale) + (2 * CardLayout.Pad(Scale)) + 1, Scale, Scale).Title);
    }

    private static bool Overlap(HudButton a, HudButton b) =>
        a.X < b.X + b.Width && b.X < a.X + a.Width && a.Y < b.Y + b.Height && b.Y < a.Y + a.Height;
}
