using Billiards.App.Net;
using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.Core.Rules;

namespace Billiards.App.Hud;

/// <summary>What the start menu's "Play online" asks for: to host a game of <paramref name="Rules"/>, or to join the game at <paramref name="Address"/> with <paramref name="Code"/>.</summary>
/// <param name="Rules">The game to host, or null to join.</param>
/// <param name="Address">The host's <c>HOST[:PORT]</c> (joining).</param>
/// <param name="Code">The host's code (joining).</param>
public sealed record OnlineRequest(GameRules? Rules, string? Address = null, string? Code = null);

// "Play online": host (choose the game, then wait showing the code) or join (type the host's
// address and the code). The game itself is started by whoever listens to OnlineRequested (the
// same host and join as the verbs); the menu shows the attempt's state it is told (OnlineStatus).
public sealed partial class MenuNode
{
    /// <summary>Longest address typed on the Join page.</summary>
    public const int MaxAddressLength = 64;

    /// <summary>Signal: the start menu asks to host a game (with <see cref="StartSettings"/>' physics) or to join one.</summary>
    public event Action<OnlineRequest>? OnlineRequested;

    /// <summary>Signal: the host stopped waiting for a player (Cancel on the code's page).</summary>
    public event Action? HostingCancelled;

    /// <summary>The host's address typed on the Join page (<c>HOST[:PORT]</c>).</summary>
    public string JoinAddress { get; set; } = "";

    /// <summary>The code typed on the Join page.</summary>
    public string JoinCode { get; set; } = "";

    /// <summary>What the online pages say of the attempt now (connecting, or why it failed), or null.</summary>
    public string? OnlineStatus { get; set; }

    /// <summary>The hosted game's code and where it listens (shown while it waits for a player), or null.</summary>
    public (string Code, int Port, string Addresses)? Hosting { get; private set; }

    /// <summary>Shows the hosted game's code and where it listens until a player joins (then the game shows by itself).</summary>
    public void ShowHosting(string code, int port, string addresses)
    {
        Hosting = (code, port, addresses);
        OnlineStatus = null;
        ShowStart(MenuPage.Hosting);
    }

    /// <summary>True while a line of the Join page takes what is typed (every letter and digit is its own there, not a key of the game).</summary>
    public bool IsTyping => Page == MenuPage.Join && _focus is 0 or 1;

    private static bool IsOnlinePage(MenuPage page) => page is MenuPage.Online or MenuPage.Host or MenuPage.Join or MenuPage.Hosting;

    // The hosted game's page closes once a player joined.
    private void ProcessOnline()
    {
        if (Page == MenuPage.Hosting && FindInTree<OnlineNode>() is { Watch.State: not LinkState.Waiting })
        {
            Hosting = null;
            Resume();
        }
    }

    private MenuPage OnlineBack()
    {
        if (Page == MenuPage.Hosting)
        {
            Hosting = null;
            HostingCancelled?.Invoke();
            return MenuPage.Start;
        }
        OnlineStatus = null;
        return Page == MenuPage.Online ? MenuPage.Start : MenuPage.Online;
    }

    private static string OnlineSubtitle(MenuPage page) => page switch
    {
        MenuPage.Host => "Host a game: choose it, then give the other player the code",
        MenuPage.Join => "Join a game: the host's address and the code it shows",
        MenuPage.Hosting => "Hosting: give the other player this code",
        _ => "Play online: two computers, one game",
    };

    // The Join page's fields take what is typed: letters, digits, '.', ':' (';') and '-' in the
    // address, letters and digits in the code; Backspace deletes, Enter goes on. False for a key
    // the page's buttons take (the arrows, Tab, Escape).
    private bool TypeOnline(Key key, bool shift)
    {
        if (!IsTyping)
        {
            return false;
        }
        bool address = _focus == 0;
        char? c = key switch
        {
            >= Key.A and <= Key.Z => (char)((address ? 'a' : 'A') + (key - Key.A)),
            >= Key.D0 and <= Key.D9 => (char)('0' + (key - Key.D0)),
            Key.Period when address => '.',
            Key.Semicolon when address => ':',
            Key.Minus when address && !shift => '-',
            _ => null,
        };
        if (c is { } ch)
        {
            if (address && JoinAddress.Length < MaxAddressLength)
            {
                JoinAddress += ch;
            }
            else if (!address && JoinCode.Length < MessageCodec.CodeLength)
            {
                JoinCode += ch;
            }
            return true;
        }
        switch (key)
        {
            case Key.Backspace:
                if (address && JoinAddress.Length > 0)
                {
                    JoinAddress = JoinAddress[..^1];
                }
                else if (!address && JoinCode.Length > 0)
                {
                    JoinCode = JoinCode[..^1];
                }
                return true;
            case Key.Enter when address:
                _focus = 1;
                return true;
            case Key.Enter:
                Join();
                return true;
            default:
                return false;
        }
    }

    private void Join()
    {
        string address = JoinAddress.Trim();
        if (address.Length == 0)
        {
            OnlineStatus = "Type the host's address first (its name or its number, and :port if not 7538).";
            _focus = 0;
            return;
        }
        if (!MessageCodec.IsCode(JoinCode))
        {
            OnlineStatus = $"The code is {MessageCodec.CodeLength} letters and digits (no 0, O, 1 or I), as the host shows it.";
            _focus = 1;
            return;
        }
        OnlineStatus = $"Connecting to {address}...";
        OnlineRequested?.Invoke(new OnlineRequest(null, address, JoinCode));
    }

    private void LayoutOnline(ref float y, float wide, float line, float u, float cx, ButtonRow row)
    {
        float buttonH = line + (10 * u), gap = 6 * u;
        switch (Page)
        {
            case MenuPage.Online:
                _labels.Add(new HudLabel(cx, y, "One computer hosts and shows a code; the other joins with the host's address and that code.", 1, Centred: true));
                y += 3 * line;
                foreach (var (label, act) in new (string, Action)[] { ("Host a game", () => Go(MenuPage.Host)), ("Join a game", () => Go(MenuPage.Join)), ("Back", Back) })
                {
                    row(y, wide, [(label, act, false)]);
                    y += buttonH + gap;
                }
                break;
            case MenuPage.Host:
            {
                y = GameRow(y, line, u, cx, row);
                // The physics as Settings offers them: the joiner gets the host's.
                _labels.Add(new HudLabel(cx, y, "Physics (the other player gets the host's)", 1, Gold: true, Centred: true));
                y += line + (2 * u);
                float physicsW = 260 * u;
                row(y, physicsW, [($"Cushion: {CushionName(StartSettings.Cushion)}", NextCushion, false)]);
                y += buttonH + gap;
                row(y, physicsW, [($"Cloth: {ClothName(StartSettings.Cloth)}", NextCloth, false)]);
                y += buttonH + (2 * line);
                int hostAt = _buttons.Count;
                row(y, wide, [("Host", () => OnlineRequested?.Invoke(new OnlineRequest(StartGame)), false), ("Back", Back, false)]);
                y += buttonH + gap;
                if (_focus < 0)
                {
                    _focus = hostAt;
                }
                break;
            }
            case MenuPage.Join:
            {
                float fieldW = (HudFont.Width($"Address: {new string('m', 24)}") + 16) * u;
                row(y, fieldW, [($"Address: {JoinAddress}{(_focus == 0 ? "_" : "")}", () => _focus = 0, false)]);
                y += buttonH + gap;
                row(y, fieldW, [($"Code: {JoinCode}{(_focus == 1 ? "_" : "")}", () => _focus = 1, false)]);
                y += buttonH + gap;
                _labels.Add(new HudLabel(cx, y + (line / 2), "Type on the line chosen (click it, or Up and Down); Enter goes on.", 1, Centred: true));
                y += 2 * line;
                row(y, wide, [("Join", Join, false), ("Back", Back, false)]);
                y += buttonH + gap;
                break;
            }
            case MenuPage.Hosting when Hosting is { } h:
                _labels.Add(new HudLabel(cx, y, "The code", 1, Gold: true, Centred: true));
                y += line + (2 * u);
                _labels.Add(new HudLabel(cx, y, h.Code, 3, Gold: true, Centred: true));
                y += (3 * line) + (4 * u);
                _labels.Add(new HudLabel(cx, y, "Waiting for a player to join...", 1, Centred: true));
                y += 2 * line;
                _labels.Add(new HudLabel(cx, y, "The other player chooses Play online, then Join a game, and types", 1, Centred: true));
                y += line + (2 * u);
                _labels.Add(new HudLabel(cx, y, $"this computer's address ({h.Addresses}, port {h.Port}) and the code.", 1, Centred: true));
                y += 2 * line;
                row(y, wide, [("Cancel", Back, false)]);
                y += buttonH + gap;
                break;
        }
        if (OnlineStatus is { } status)
        {
            _labels.Add(new HudLabel(cx, y + line, status, 1, Gold: true, Centred: true));
        }
    }
}
