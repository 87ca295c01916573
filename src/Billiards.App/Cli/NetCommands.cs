using System.CommandLine;
using System.Net;
using System.Security.Cryptography;
using Billiards.App.Game;
using Billiards.App.Net;
using Billiards.App.Platform;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Cli;

/// <summary>
/// <c>host</c> and <c>join</c>: a game between two machines (docs/network.md). The host chooses
/// the game and the players' names and waits for one player with its code; the joiner connects,
/// shakes hands (version, code, physics) and gets the game. Both then open the game window, each
/// playing its own seat, the other seat remote. Arguments are checked and the connection made
/// before any window opens: a bad argument or a refusal is one line and a non-zero exit.
/// </summary>
public static class NetCommands
{
    /// <summary>The port a host listens on by default.</summary>
    public const int DefaultPort = 7538;

    /// <summary>Adds <c>host</c> and <c>join</c> to the root command; log lines go to <paramref name="stderr"/>, the host's code to <paramref name="stdout"/>.</summary>
    public static void AddTo(RootCommand root, TextWriter stdout, TextWriter stderr)
    {
        ArgumentNullException.ThrowIfNull(root);
        var log = TextWriter.Synchronized(stderr);
        var port = new Option<int?>("--port") { Description = $"The TCP port to listen on (default {DefaultPort})." };
        var code = new Option<string?>("--code") { Description = $"The {MessageCodec.CodeLength}-character code the joiner must give (letters and digits without 0, O, 1, I); default: a new random one, shown." };
        var players = new Option<string?>("--players") { Description = "The players' names, A,B: the host's first (default Player 1,Player 2)." };
        var rules = new Option<string?>("--rules") { Description = $"The game: {VerbHelp.Games} (default eight-ball)." };
        var (script, record, stats) = PlayOptions();
        var host = new Command("host", VerbHelp.Verb("Wait for one player to join and play a game with them over the network.", "host")) { port, code, players, rules, script, record, stats };
        host.SetAction(parse => Host(new HostOptions(parse.GetValue(port), parse.GetValue(code), parse.GetValue(players), parse.GetValue(rules), parse.GetValue(script), parse.GetValue(record), parse.GetValue(stats)) { OpenAudio = PlayCommand.OpenAudio }, stdout, log.WriteLine, title => PlatformWiring.Open(title)));
        root.Add(host);

        var address = new Argument<string>("address") { Description = $"HOST[:PORT]: the host's name or address (default port {DefaultPort})." };
        var joinCode = new Option<string?>("--code") { Description = "The host's code (required)." };
        var (joinScript, joinRecord, joinStats) = PlayOptions();
        var join = new Command("join", VerbHelp.Verb("Join a game hosted on another machine.", "join")) { address, joinCode, joinScript, joinRecord, joinStats };
        join.SetAction(parse => Join(parse.GetValue(address)!, parse.GetValue(joinCode), new PlayCommand.PlayOptions(parse.GetValue(joinScript), parse.GetValue(joinStats)) { Record = parse.GetValue(joinRecord) }, log.WriteLine, title => PlatformWiring.Open(title), openAudio: PlayCommand.OpenAudio));
        root.Add(join);
    }

    private static (Option<string?> Script, Option<string?> Record, Option<string?> Stats) PlayOptions() => (
        new Option<string?>("--script") { Description = "Replay a timed list of input events, as play --script (a wait for rest also waits for the other player's turn)." },
        new Option<string?>("--record") { Description = "Write the game record when the window closes, as play --record (both sides write the same record)." },
        new Option<string?>("--stats") { Description = "Write the frame statistics when the game ends, as play --stats." });

    /// <summary>The host's options.</summary>
    public sealed record HostOptions(int? Port, string? Code, string? Players, string? Rules, string? Script, string? Record, string? Stats)
    {
        /// <summary>How long a dropped joiner may take to come back (<see cref="PeerWatch.DefaultComeBack"/> when null).</summary>
        public TimeSpan? ComeBack { get; init; }

        /// <summary>The address to listen on (all of this machine's by default).</summary>
        public IPAddress? Address { get; init; }

        /// <summary>Called with the listener once it listens (tests read its port).</summary>
        public Action<NetHost>? Listening { get; init; }

        /// <summary>Listen on a port the system chooses instead of <see cref="Port"/> (tests).</summary>
        public bool AnyPort { get; init; }

        /// <summary>The clock of the game (the real one when null).</summary>
        public IClock? Clock { get; init; }

        /// <summary>Opens the sound output; silence when null (tests).</summary>
        public Func<Audio.IAudioOutput>? OpenAudio { get; init; }
    }

    /// <summary>The host: checks the arguments, listens, and plays the game in a window; returns the exit code.</summary>
    public static int Host(HostOptions options, TextWriter stdout, Action<string> log, Func<string, GamePlatform> openPlatform, Action<GameHost>? started = null)
    {
        ArgumentNullException.ThrowIfNull(options);
        ArgumentNullException.ThrowIfNull(stdout);
        int port = options.AnyPort ? 0 : options.Port ?? DefaultPort;
        if (port is < 1 or > 65535 && !options.AnyPort)
        {
            throw new CliException($"--port {port}: expected 1-65535");
        }
        string code = options.Code is { } given ? CheckCode(given) : NewCode();
        var gameRules = options.Rules is { } r ? (RuleNames.TryParseGame(r, out var parsed) ? parsed : throw new CliException($"--rules {r}: unknown game (expected {string.Join(", ", RuleNames.GameNames)})")) : GameRules.EightBall;
        var names = Names(options.Players);
        var scene = SceneLoader.Load(PlayCommand.FindRulesScene(gameRules));
        using var online = Listen(scene, gameRules, names, code, options.Address ?? IPAddress.Any, port, log, options.ComeBack);
        var listener = online.Link.Listener!;
        options.Listening?.Invoke(listener);
        stdout.WriteLine($"host: waiting for a player on port {listener.Port} with the code {code} (billiards join THIS-HOST:{listener.Port} --code {code})");
        stdout.Flush();
        var play = new PlayCommand.PlayOptions(options.Script, options.Stats) { Record = options.Record, Online = online, Started = started };
        return PlayCommand.Play(null, openPlatform, clock: options.Clock, options: play, openAudio: options.OpenAudio);
    }

    /// <summary>A new random code: <see cref="MessageCodec.CodeLength"/> characters of <see cref="MessageCodec.CodeAlphabet"/>.</summary>
    public static string NewCode() => new(RandomNumberGenerator.GetItems<char>(MessageCodec.CodeAlphabet, MessageCodec.CodeLength));

    /// <summary>
    /// The host's game of <paramref name="rules"/> on <paramref name="scene"/>'s table and physics
    /// between <paramref name="names"/> (the host's seat first), listening on
    /// <paramref name="address"/>:<paramref name="port"/> for one player with <paramref name="code"/>:
    /// what <c>host</c> and the start menu's "Play online" both start.
    /// </summary>
    /// <exception cref="EnvironmentException">When the port cannot be listened on.</exception>
    public static OnlineGame Listen(Scene scene, GameRules rules, IReadOnlyList<string> names, string code, IPAddress address, int port, Action<string> log, TimeSpan? comeBack = null)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(names);
        var opening = scene.Game is { } o && o.Rules == rules ? o : new GameState(rules) { Target = Ruleset.For(rules).DefaultTarget };
        var setup = new GameSetup(scene.Table, scene.Physics, scene.Rack?.Seed ?? 1, opening with { Call = null, PushOut = false, Placement = null, Players = new PerPlayer<string>(names[0], names[1]) });
        var game = Handshake.Describe(setup);
        OnlineGame? online = null;
        var listener = new NetHost(address, port, () => new Hello(Handshake.ProgramVersion, code, game, online?.Node?.ShotsSoFar ?? 0), log);
        var match = new MatchSetup(rules, [new Seat(names[0]), new Seat(names[1]) { Kind = SeatKind.Remote }]) { Game = setup };
        var link = new OnlineLink(true, code, log)
        {
            Listener = listener,
            ComeBack = comeBack,
            WaitingLine = $"Waiting for a player: code {code}, port {listener.Port}.",
        };
        online = new OnlineGame(scene, match, link);
        return online;
    }

    /// <summary>
    /// Connects to <paramref name="hostName"/>:<paramref name="port"/> with <paramref name="code"/>
    /// and shakes hands: the joiner's game as the host gave it (what <c>join</c> and the start
    /// menu's "Play online" both start).
    /// </summary>
    /// <exception cref="CliException">The host refused, or its game differs here.</exception>
    /// <exception cref="EnvironmentException">Nothing listens there, or no answer in time.</exception>
    public static OnlineGame Connect(string hostName, int port, string code, Action<string> log, TimeSpan? comeBack = null)
    {
        ArgumentNullException.ThrowIfNull(log);
        var (connection, setup, hello) = NetJoin.Connect(hostName, port, code, log);
        var names = setup.Start.Players;
        var match = new MatchSetup(setup.Rules, [new Seat(names.First) { Kind = SeatKind.Remote }, new Seat(names.Second)]) { Game = setup };
        var link = new OnlineLink(false, code, log)
        {
            Connection = connection,
            ShotsAtJoin = hello.Shots,
            ComeBack = comeBack,
            Rejoin = () =>
            {
                var (again, game, back) = NetJoin.Connect(hostName, port, code, log);
                if (!Equals(game, setup))
                {
                    again.Close("another game");
                    throw new CliException("join: the host came back with another game");
                }
                return (again, back.Shots);
            },
        };
        log($"join: joined {hostName}:{port}: {Ruleset.For(setup.Rules).Title}, {names.First} (the host) against {names.Second}");
        return new OnlineGame(SceneOf(setup), match, link);
    }

    /// <summary>The joiner: checks the arguments, connects and shakes hands, and plays the game in a window; returns the exit code.</summary>
    public static int Join(string address, string? code, PlayCommand.PlayOptions options, Action<string> log, Func<string, GamePlatform> openPlatform, TimeSpan? comeBack = null, IClock? clock = null, Func<Audio.IAudioOutput>? openAudio = null)
    {
        ArgumentNullException.ThrowIfNull(options);
        var (hostName, port) = NetJoin.ParseAddress(address, DefaultPort);
        if (code is null)
        {
            throw new CliException("join: --code is required (the code the host shows)");
        }
        code = CheckCode(code);
        // The files are checked before the connection, so that a bad path is not found after the handshake.
        _ = options.Script is { } s ? InputScript.Load(s) : null;
        _ = options.Record is { } rec ? OutputFiles.Check("--record", rec, ".json") : null;
        _ = options.Stats is { } st ? OutputFiles.Check("--stats", st, ".json") : null;
        using var online = Connect(hostName, port, code, log, comeBack);
        return PlayCommand.Play(null, openPlatform, clock: clock, options: options with { Online = online }, openAudio: openAudio);
    }

    /// <summary>The scene the joiner's window shows: the host's table and physics with the game's rack and its ball set (carom's three balls and cloth for three-cushion).</summary>
    public static Scene SceneOf(GameSetup setup)
    {
        ArgumentNullException.ThrowIfNull(setup);
        var ruleset = Ruleset.For(setup.Rules);
        return Scene.Of(setup.Position ?? setup.Racked(0), setup.Table, setup.Physics, ruleset.BallSet, rules: setup.Rules.ToName())
            with { Path = "online", Name = $"{ruleset.Title} online" };
    }

    /// <summary>A code as given (case does not matter), or one line saying what a code is.</summary>
    public static string CheckCode(string code)
    {
        ArgumentNullException.ThrowIfNull(code);
        string upper = code.Trim().ToUpperInvariant();
        return MessageCodec.IsCode(upper) ? upper
            : throw new CliException($"--code {code}: expected {MessageCodec.CodeLength} letters and digits (no 0, O, 1 or I)");
    }

    // The two names of --players: people only (the computer does not play over the network).
    private static string[] Names(string? players)
    {
        string[] parts = (players ?? "human,human").Split(',');
        if (parts.Length != 2)
        {
            throw new CliException($"--players {players}: expected two names A,B (the host's first)");
        }
        var seats = new Seat[2];
        for (int i = 0; i < 2; i++)
        {
            seats[i] = Seat.Parse(parts[i], i) is { Kind: SeatKind.Person } seat ? seat
                : throw new CliException($"--players {players}: \"{parts[i]}\" is not a person's name (1-{Seat.MaxNameLength} characters; the computer does not play over the network)");
        }
        return [.. PlayCommand.Distinct(seats).Select(s => s.Name)];
    }
}

/// <summary>
/// A networked game for <see cref="PlayCommand.Play"/>: the scene shown, the match (the game
/// exactly, one seat remote) and the link to the peer. Disposing it closes the host's listener
/// (and its peer) or the joiner's connection.
/// </summary>
/// <param name="Scene">The scene (table and physics).</param>
/// <param name="Match">The match, its <see cref="MatchSetup.Game"/> set.</param>
/// <param name="Link">The host's listener or the joiner's connection.</param>
public sealed record OnlineGame(Scene Scene, MatchSetup Match, OnlineLink Link) : IDisposable
{
    /// <summary>The window's network node once the game is in a window (<see cref="Attach"/>).</summary>
    public OnlineNode? Node { get; private set; }

    /// <summary>Puts the game's network node into <paramref name="host"/>'s tree (the peer's strokes shown at a quarter of the pace when <paramref name="fast"/>).</summary>
    public OnlineNode Attach(GameHost host, bool fast)
    {
        ArgumentNullException.ThrowIfNull(host);
        Node = host.Tree.Root.AddChild(new OnlineNode(Link) { Fast = fast });
        return Node;
    }

    /// <inheritdoc />
    public void Dispose()
    {
        Link.Listener?.Dispose();
        if (Link.Connection is { } connection)
        {
            connection.Close("the game closed");
            connection.Dispose();
        }
    }
}
