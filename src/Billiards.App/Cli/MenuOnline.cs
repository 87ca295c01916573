using System.Net;
using System.Net.NetworkInformation;
using System.Net.Sockets;
using Billiards.App.Game;
using Billiards.App.Hud;
using Billiards.App.Platform;
using Billiards.App.Net;
using Billiards.Core.Scenes;

namespace Billiards.App.Cli;

/// <summary>
/// The start menu's "Play online" between two frames, through the same steps as <c>host</c> and
/// <c>join</c> (<see cref="NetCommands.Listen"/>, <see cref="NetCommands.Connect"/>): hosting
/// listens at once; joining shakes hands on its own task while the window goes on drawing, and
/// a failure is one line on the menu. It owns the online game shown, and closes it when another
/// game replaces it.
/// </summary>
/// <param name="hostAt">Where a hosted game listens (this machine's every address on <see cref="NetCommands.DefaultPort"/>, or another port when that one is taken).</param>
/// <param name="log">Where the network's log lines go.</param>
public sealed class MenuOnline(IPEndPoint hostAt, Action<string> log) : IDisposable
{
    private (OnlineRequest Request, Scene Scene)? _asked;
    private Task<OnlineGame>? _joining;

    /// <summary>The online game in the window now, or null.</summary>
    public OnlineGame? Current { get; private set; }

    /// <summary>Takes the menu's request (hosting on <paramref name="scene"/>'s table and physics); it is carried out by the next <see cref="Poll"/>.</summary>
    public void Ask(OnlineRequest request, Scene scene) => _asked = (request, scene);

    /// <summary>
    /// Carries out what was asked and looks at a handshake under way: the online game to show now
    /// (the previous one closed), or null; a failure is said on <paramref name="menu"/>. Never waits on the network.
    /// </summary>
    public OnlineGame? Poll(MenuNode menu)
    {
        ArgumentNullException.ThrowIfNull(menu);
        if (_asked is { } asked)
        {
            _asked = null;
            if (asked.Request.Rules is { } rules)
            {
                try
                {
                    return Show(Host(asked.Scene, rules));
                }
                catch (EnvironmentException e)
                {
                    menu.OnlineStatus = e.Message;
                }
            }
            else if (_joining is null)
            {
                try
                {
                    var (name, port) = NetJoin.ParseAddress(asked.Request.Address!, NetCommands.DefaultPort);
                    string code = asked.Request.Code!;
                    _joining = BackgroundWork.RunBlocking(() => NetCommands.Connect(name, port, code, log));
                }
                catch (CliException e)
                {
                    menu.OnlineStatus = e.Message;
                }
            }
        }
        if (_joining is { IsCompleted: true } done)
        {
            _joining = null;
            if (done.IsCompletedSuccessfully)
            {
                return Show(done.Result);
            }
            var e = done.Exception!.InnerException!;
            menu.OnlineStatus = e is CliException or EnvironmentException ? e.Message : $"join: {e.Message}";
        }
        return null;
    }

    /// <summary>A game at this table replaced the online one: it is closed.</summary>
    public void Drop()
    {
        Current?.Dispose();
        Current = null;
    }

    /// <summary>This machine's addresses a player on the network can reach, in words (IPv4, not loopback), or "this computer's name" when none.</summary>
    public static string Addresses()
    {
        try
        {
            var all = NetworkInterface.GetAllNetworkInterfaces()
                .Where(n => n.OperationalStatus == OperationalStatus.Up && n.NetworkInterfaceType != NetworkInterfaceType.Loopback)
                .SelectMany(n => n.GetIPProperties().UnicastAddresses)
                .Select(a => a.Address)
                .Where(a => a.AddressFamily == AddressFamily.InterNetwork && !IPAddress.IsLoopback(a))
                .Select(a => a.ToString())
                .Distinct()
                .Take(3)
                .ToList();
            return all.Count > 0 ? string.Join(" or ", all) : Dns.GetHostName();
        }
        catch (NetworkInformationException)
        {
            return Dns.GetHostName();
        }
    }

    /// <inheritdoc />
    public void Dispose()
    {
        Drop();
        if (_joining is { } joining)
        {
            // A handshake still under way is closed once it ends.
            joining.ContinueWith(t => t.Result.Dispose(), TaskContinuationOptions.OnlyOnRanToCompletion);
        }
    }

    private OnlineGame Host(Scene scene, Core.Rules.GameRules rules)
    {
        string code = NetCommands.NewCode();
        string[] names = ["Player 1", "Player 2"];
        OnlineGame game;
        try
        {
            game = NetCommands.Listen(scene, rules, names, code, hostAt.Address, hostAt.Port, log);
        }
        catch (EnvironmentException) when (hostAt.Port != 0)
        {
            // The port is taken (another game hosted here): the system chooses one, and the page says which.
            game = NetCommands.Listen(scene, rules, names, code, hostAt.Address, 0, log);
        }
        log($"host: waiting for a player on port {game.Link.Listener!.Port} with the code {code}");
        return game;
    }

    private OnlineGame Show(OnlineGame game)
    {
        Drop();
        Current = game;
        return game;
    }
}
