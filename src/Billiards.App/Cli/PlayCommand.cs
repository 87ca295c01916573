using System.CommandLine;
using Billiards.App.Audio;
using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.App.Practice;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Cli;

/// <summary>
/// <c>play [SCENE]</c>: the game, and the default verb (no verb plays <see cref="DefaultScene"/>).
/// The scene is loaded and checked before any window opens, so a bad scene is one line on stderr
/// and a non-zero exit.
/// </summary>
public static class PlayCommand
{
    /// <summary>The scene played without arguments: 8-ball on a 9 ft table.</summary>
    public const string DefaultScene = "assets/scenes/eight-ball.json";

    /// <summary>Adds the <c>play</c> verb to the root command and makes it the root's own action.</summary>
    public static void AddTo(RootCommand root)
    {
        var scene = new Argument<string?>("scene")
        {
            Description = $"The scene file (billiards-scene/1 JSON); default {DefaultScene}.",
            Arity = ArgumentArity.ZeroOrOne,
        };
        var script = new Option<string?>("--script") { Description = $"Replay a timed list of input events ({InputScript.Format} JSON); the game closes when it ends." };
        var stats = new Option<string?>("--stats") { Description = $"Write per-second frame rates, frame-time percentiles and input-to-frame delays ({FrameStats.Format} JSON) when the game ends." };
        var rules = new Option<string?>("--rules") { Description = $"The game: {VerbHelp.Games} (default: the scene's rules)." };
        var players = new Option<string?>("--players") { Description = $"The two players, A,B: each a name or human (a person), or computer:LEVEL (1-5; also cpu:LEVEL); default {DefaultPlayers}." };
        var record = new Option<string?>("--record") { Description = $"Write the game ({GameRecordFile.Format} JSON, which replay reads) when the window closes." };
        var cap = new Option<double?>("--fps-cap") { Description = $"The most frames a second (0: no cap); default the display's refresh rate, else {PlatformWiring.DefaultFrameCap}." };
        var fast = new Option<bool>("--fast-computer") { Description = $"The computer turns to its aim and strikes in {ComputerPlayerNode.FastShare:0%} of the time (default: {ComputerPlayerNode.StrokeSeconds:0.0} s from its aim to its stroke)." };
        var practice = new Option<bool>("--practice") { Description = $"Practice on the scene (default {PracticeScene}): no referee; drag, add and remove balls, retry, save and load positions." };
        var drill = new Option<string?>("--drill") { Description = "Play a drill: a name of assets/drills (e.g. stop-shot) or a drill file." };
        var data = new Option<string?>("--data") { Description = $"The folder for drill results and saved positions (default ${DataFolder.Variable}, else the user's data folder)." };
        var save = new Option<string?>("--save") { Description = "Where practice saves its position (F5) and loads it from (F9); default practice/position.json in the data folder." };
        var takeBacks = new Option<bool>("--take-backs") { Description = $"The players allow take-backs: {TakeBackNode.UndoKey} puts the game back before the last shot (off by default; practice always allows them)." };
        var command = new Command("play", VerbHelp.Verb("Play a game, practice or a drill in a window (the default verb).", "play")) { scene, script, stats, rules, players, record, cap, fast, practice, drill, data, save, takeBacks };
        command.SetAction(parse => Play(parse.GetValue(scene), title => PlatformWiring.Open(title, FrameCap(parse.GetValue(cap))), options: new PlayOptions(parse.GetValue(script), parse.GetValue(stats))
        {
            Rules = parse.GetValue(rules),
            Players = parse.GetValue(players),
            Record = parse.GetValue(record),
            FastComputer = parse.GetValue(fast),
            TakeBacks = parse.GetValue(takeBacks),
            Practice = parse.GetValue(practice),
            Drill = parse.GetValue(drill),
            DataFolder = parse.GetValue(data),
            SavePath = parse.GetValue(save),
            StartMenu = parse.GetValue(scene) is null && parse.GetValue(rules) is null && parse.GetValue(players) is null
                && parse.GetValue(script) is null && parse.GetValue(stats) is null && parse.GetValue(record) is null
                && !parse.GetValue(practice) && parse.GetValue(drill) is null,
        }, openAudio: OpenAudio));
        root.Add(command);
        root.SetAction(_ => Play(null, PlatformWiring.Open, options: new PlayOptions(null, null) { StartMenu = true }, openAudio: OpenAudio));
    }

    /// <summary>
    /// The window's title: the game and its players for a match (the scene's own name says only
    /// what the scene was written for: "8-ball for two players" whatever the game chosen), else
    /// the scene's name.
    /// </summary>
    public static string TitleFor(Scene scene, MatchSetup? match)
    {
        ArgumentNullException.ThrowIfNull(scene);
        if (match is { } m)
        {
            string game = Ruleset.For(m.Rules).Title;
            return $"{PlatformWiring.WindowTitle}: {game}, {m.Players[0].Name} vs {m.Players[1].Name}";
        }
        return scene.Name is { } name ? $"{PlatformWiring.WindowTitle}: {name}" : PlatformWiring.WindowTitle;
    }

    /// <summary>The <c>--fps-cap</c> value checked: null (the display's), 0 (none) or a rate up to <see cref="PlatformWiring.MaxFrameCap"/>.</summary>
    public static double? FrameCap(double? value) =>
        value is not { } v || (double.IsFinite(v) && v >= 0 && v <= PlatformWiring.MaxFrameCap)
            ? value
            : throw new CliException(string.Create(System.Globalization.CultureInfo.InvariantCulture, $"--fps-cap {v}: expected 0 (no cap) to {PlatformWiring.MaxFrameCap} frames a second"));

    /// <summary>Loads the scene, opens the platform and runs the game until the window closes.</summary>
    /// <param name="scenePath">The scene, or null for <see cref="DefaultScene"/>.</param>
    /// <param name="openPlatform">Opens the window and renderer for a window title.</param>
    /// <param name="createSimulation">Makes the simulation; <see cref="SimulationFactory.Create"/> by default.</param>
    /// <param name="clock">The clock; the real one by default.</param>
    /// <returns>The exit code.</returns>
    /// <param name="options">A script to replay and a stats file to write, or null.</param>
    /// <param name="openAudio">Opens the sound output; silence by default (tests).</param>
    public static int Play(string? scenePath, Func<string, GamePlatform> openPlatform, Func<Scene, Simulation>? createSimulation = null, IClock? clock = null, PlayOptions? options = null, Func<IAudioOutput>? openAudio = null)
    {
        var gameRules = ParseRules(options?.Rules);
        string dataFolder = options?.DataFolder is { } folder ? OutputFiles.CheckFolder("--data", folder) : DataFolder.Path();
        var drill = options?.Drill is { } drillName ? DrillLibrary.Load(drillName) : null;
        bool practice = options?.Practice == true || drill is not null;
        if (practice && (gameRules is not null || options?.Players is not null))
        {
            throw new CliException($"{(drill is null ? "--practice" : "--drill")}: practice has no match (leave out --rules and --players)");
        }
        if (drill is not null && scenePath is not null)
        {
            throw new CliException($"--drill {options!.Drill}: a drill brings its own position (leave out the scene {scenePath})");
        }
        var online = options?.Online;
        string path = online?.Scene.Path ?? drill?.Scene.Path ?? scenePath ?? (practice ? FindPracticeScene() : gameRules is { } chosen ? FindRulesScene(chosen) : FindDefaultScene());
        var scene = online?.Scene ?? drill?.Scene ?? SceneLoader.Load(path);
        string savePath = options?.SavePath is { } sp ? OutputFiles.Check("--save", sp, ".json") : Path.Combine(dataFolder, "practice", "position.json");
        PracticeSetup? practiceSetup = practice ? PracticeFor(scene, drill, savePath, dataFolder) : null;
        if (practiceSetup is not null)
        {
            // Practice sets the cue to a scene's shot instead of playing it.
            scene = scene with { Shot = null };
        }
        // The start menu's physics choice, remembered between runs, makes the games it starts.
        bool startMenu = options?.StartMenu == true && options.Script is null && options.Stats is null && options.Record is null;
        string settingsPath = options?.SettingsPath ?? GameSettings.DefaultPath();
        var settings = startMenu ? GameSettings.Load(settingsPath, Console.Error) : GameSettings.Default;
        if (options?.TakeBacks == true)
        {
            settings = settings with { TakeBacks = true };
        }
        if (startMenu)
        {
            scene = settings.Apply(scene);
        }
        var script = options?.Script is { } scriptPath ? InputScript.Load(scriptPath) : null;
        string? statsPath = options?.Stats is { } s ? OutputFiles.Check("--stats", s, ".json") : null;
        string? recordPath = options?.Record is { } r ? OutputFiles.Check("--record", r, ".json") : null;
        var match = online?.Match ?? (practice ? null : MatchFor(scene, gameRules, options?.Players));
        if (recordPath is not null && (match is null || !scene.Balls.Any(b => b.Id == scene.CueBall)))
        {
            throw new CliException($"--record {recordPath}: {path} has no match to record (it names no rules and no --rules was given, or it has no cue ball)");
        }
        string title = practiceSetup is not null ? PracticeTitle(practiceSetup) : TitleFor(scene, match);
        using var platform = OpenOrExplain(openPlatform, title);
        var gameClock = new ScriptClock(clock ?? new StopwatchClock());
        using var scripted = script is null ? null : new ScriptedInput(platform.Window, script, gameClock);
        using var audio = openAudio?.Invoke() ?? new SilentAudio();
        if (startMenu)
        {
            audio.Muted = settings.Muted;
        }
        using var host = new GameHost(scene, createSimulation ?? SimulationFactory.Create, (IGameWindow?)scripted ?? platform.Window, gameClock, match, practiceSetup);
        host.Tree.Root.AddChild(new AudioNode(audio));
        bool fastComputer = options?.FastComputer == true;
        Pace(host, fastComputer || settings.FastComputer);
        AllowTakeBacks(host, settings.TakeBacks);
        var onlineNode = online?.Attach(host, script is not null || fastComputer);
        options?.Started?.Invoke(host);
        if (scripted is not null)
        {
            // A script's pixels were recorded on the whole window's view.
            host.Tree.Root.GetInTree<Camera.CameraNode>().FramesBelowHud = false;
            host.TimeScale = script!.Speed;
            scripted.IsAtRest = () => host.IsSettled;
            if (host.Tree.Root.FindInTree<ComputerPlayerNode>() is { } computer)
            {
                // A scripted game must be the same game on any machine: no search is cut short by the clock.
                computer.BudgetMs = 120_000;
            }
        }
        var stats = statsPath is null ? null : new FrameStats();
        var instantReplay = host.Tree.Root.FindInTree<InstantReplayNode>();
        bool warm = false;
        host.FrameStarting += now =>
        {
            // The first frame loads the table and compiles the shaders: the script and the
            // stats start with the second, so their second 0 is a second of play.
            if (!warm)
            {
                warm = true;
                return;
            }
            stats?.FrameStarted(now, Platform.CpuClock.ProcessSeconds(), instantReplay is { IsActive: true });
            if (scripted is not null)
            {
                scripted.Pump(now);
                if (scripted.Finished)
                {
                    platform.Window.Close();
                }
            }
        };
        if (scripted is not null && stats is not null)
        {
            scripted.Raised += (e, _) => stats.InputRaised(e, e.Time + scripted.Waited);
        }
        // A game from the command line opens the start menu only from its result panel (Menu), and
        // a choice made there replaces it as it does from plain play; a scripted, measured or
        // recorded run keeps its one game.
        if (online is null && (startMenu || (script is null && statsPath is null && recordPath is null && match is not null)))
        {
            host.World.Menu.StartSettings = host.World.Menu.PlayedSettings = settings;
            platform.SetGraphics?.Invoke(settings.Graphics);
            using var menuOnline = new MenuOnline(options?.HostAt ?? new System.Net.IPEndPoint(System.Net.IPAddress.Any, NetCommands.DefaultPort), TextWriter.Synchronized(Console.Error).WriteLine);
            RunWithStartMenu(host, platform, (next, fast) => Pace(new GameHost(next.Scene, createSimulation ?? SimulationFactory.Create, (IGameWindow?)scripted ?? platform.Window, gameClock, next.Match, next.Practice), fastComputer || fast), audio, settingsPath, startMenu, dataFolder, menuOnline);
        }
        else
        {
            host.Run(platform.Loop, platform.Renderer);
        }
        if (stats is not null && statsPath is not null)
        {
            stats.Ended(gameClock.Now, Platform.CpuClock.ProcessSeconds());
            var (width, height) = platform.Window.FramebufferSize;
            OutputFiles.Write(statsPath, stats.ToJson(path, options?.Script, width, height, platform.GlRenderer));
        }
        if (recordPath is not null)
        {
            var matchNode = host.Tree.Root.GetInTree<MatchNode>();
            // One record per game of the session, one per line, as self-play writes them.
            var records = GameRecordFile.ToJsonLines(matchNode.Session.RecordedGames);
            OutputFiles.Write(recordPath, onlineNode is null ? records : onlineNode.Annotate(records));
        }
        return 0;
    }

    private static void AllowTakeBacks(GameHost host, bool allowed)
    {
        if (host.Tree.Root.FindInTree<MatchNode>() is { } match)
        {
            match.Session.TakeBacks = allowed;
        }
    }

    private static GameHost Pace(GameHost host, bool fast)
    {
        if (host.Tree.Root.FindInTree<ComputerPlayerNode>() is { } computer)
        {
            computer.Fast = fast;
        }
        return host;
    }

    // The start menu shows over the default game; a different choice replaces the game (a new host
    // on the same window) between two frames.
    private static void RunWithStartMenu(GameHost first, GamePlatform platform, Func<(Scene Scene, MatchSetup? Match, PracticeSetup? Practice), bool, GameHost> create, IAudioOutput audio, string settingsPath, bool showAtStart, string dataFolder, MenuOnline online)
    {
        var current = first;
        // A match (rules and players), or practice (a drill's name, or null for free practice); the start menu over it or not.
        (GameRules? Rules, Seat[]? Players, string? Drill, GameSettings Settings, bool Menu)? pending = null;
        var gallery = DrillLibrary.All();
        var drills = gallery.Select(d => (d.Name, d.Title)).ToList();
        void Listen(GameHost h)
        {
            h.World.Menu.Drills = drills;
            h.World.Menu.DrillGallery = gallery;
            h.World.Menu.StartRequested += (rules, players) => pending = (rules, players, null, h.World.Menu.StartSettings, false);
            h.World.Menu.PracticeRequested += drill => pending = (null, null, drill, h.World.Menu.StartSettings, false);
            h.World.Menu.OnlineRequested += request =>
            {
                var settings = h.World.Menu.StartSettings;
                settings.Save(settingsPath, Console.Error);
                online.Ask(request, settings.Apply(SceneLoader.Load(FindRulesScene(request.Rules ?? settings.Game))));
            };
            // A host that stops waiting gets a game at this table of the same rules, the start menu over it.
            h.World.Menu.HostingCancelled += () => pending = (h.World.Menu.StartGame, [new Seat("Player 1"), new Seat("Player 2")], null, h.World.Menu.StartSettings, true);
            // A new pace or graphics alone keeps the game: it is saved and applied here, a new game saves its own.
            h.World.Menu.SettingsChosen += chosen =>
            {
                chosen.Save(settingsPath, Console.Error);
                platform.SetGraphics?.Invoke(chosen.Graphics);
            };
        }
        // The new game takes the window (the old one is let go, the first one being the caller's).
        void Replace(GameHost next)
        {
            var settings = current.World.Menu.StartSettings;
            // The first game too stops listening to the window (its menu would still take the keys); disposing it again is harmless.
            current.Dispose();
            current = next;
            current.Tree.Root.AddChild(new AudioNode(audio));
            current.World.Menu.StartSettings = current.World.Menu.PlayedSettings = settings;
            Listen(current);
        }
        Listen(first);
        if (showAtStart)
        {
            first.World.Menu.ShowStart();
        }
        try
        {
            platform.Loop.Run(() =>
            {
                if (online.Poll(current.World.Menu) is { } game)
                {
                    Replace(create((game.Scene, game.Match, null), false));
                    game.Attach(current, fast: false);
                    platform.SetTitle?.Invoke(TitleFor(game.Scene, game.Match));
                    if (game.Link.Listener is { } listener)
                    {
                        current.World.Menu.ShowHosting(game.Link.Code, listener.Port, MenuOnline.Addresses());
                    }
                }
                if (pending is { } next)
                {
                    pending = null;
                    online.Drop();
                    next.Settings.Save(settingsPath, Console.Error);
                    var drill = next.Drill is { } name ? DrillLibrary.Load(name) : null;
                    // A drill's physics is its own: the goal was checked with it.
                    var chosen = drill?.Scene ?? next.Settings.Apply(SceneLoader.Load(next.Rules is { } r ? FindRulesScene(r) : FindPracticeScene()));
                    var setup = next.Rules is { } rules ? new MatchSetup(rules, next.Players!) : null;
                    var practice = setup is null ? PracticeFor(chosen, drill, Path.Combine(dataFolder, "practice", "position.json"), dataFolder) : null;
                    Replace(create((chosen with { Shot = practice is null ? chosen.Shot : null }, setup, practice), next.Settings.FastComputer));
                    AllowTakeBacks(current, next.Settings.TakeBacks);
                    platform.SetTitle?.Invoke(practice is not null ? PracticeTitle(practice) : TitleFor(chosen, setup));
                    current.World.Menu.StartSettings = current.World.Menu.PlayedSettings = next.Settings;
                    if (next.Menu)
                    {
                        current.World.Menu.ShowStart();
                    }
                }
                platform.Renderer.Draw(current.RunFrame());
            });
        }
        finally
        {
            if (current != first)
            {
                current.Dispose();
            }
        }
    }

    /// <summary>
    /// On Linux and the BSDs a window needs an X11 or Wayland display; without one GLFW would fail
    /// deep in its initialisation. Checked before any native library is loaded.
    /// </summary>
    /// <exception cref="EnvironmentException">When there is no display.</exception>
    public static void RequireDisplay(Func<string, string?>? environment = null)
    {
        environment ??= Environment.GetEnvironmentVariable;
        if (OperatingSystem.IsWindows() || OperatingSystem.IsMacOS())
        {
            return;
        }
        if (string.IsNullOrEmpty(environment("DISPLAY")) && string.IsNullOrEmpty(environment("WAYLAND_DISPLAY")))
        {
            throw new EnvironmentException("play: no display: DISPLAY is not set (run it in a desktop session, or under Xvfb: xvfb-run billiards play)");
        }
    }

    // No audio device (a server, CI): the game plays silently after one line on stderr.
    internal static IAudioOutput OpenAudio() => AudioOutputs.Open(Console.Error);

    // No display, no GL driver, no GLFW: an environment problem, one line and exit code 1.
    private static GamePlatform OpenOrExplain(Func<string, GamePlatform> openPlatform, string title)
    {
        try
        {
            return openPlatform(title);
        }
        catch (Exception e) when (e is InvalidOperationException or DllNotFoundException or EntryPointNotFoundException)
        {
            throw new EnvironmentException($"play: cannot open the game's window: {e.Message}", e);
        }
    }

    /// <summary>Options of <c>play</c>.</summary>
    /// <param name="Script">A <see cref="InputScript"/> file to replay, or null.</param>
    /// <param name="Stats">Where to write the <see cref="FrameStats"/>, or null.</param>
    public sealed record PlayOptions(string? Script, string? Stats)
    {
        /// <summary>The game (<c>--rules</c>), or null for the scene's.</summary>
        public string? Rules { get; init; }

        /// <summary>The players (<c>--players A,B</c>), or null for two people.</summary>
        public string? Players { get; init; }

        /// <summary>Where to write the game record (<see cref="GameRecordFile"/>), or null.</summary>
        public string? Record { get; init; }

        /// <summary>The computer plays fast (<c>--fast-computer</c>).</summary>
        public bool FastComputer { get; init; }

        /// <summary>The players allow take-backs (<c>--take-backs</c>); the start menu's setting otherwise.</summary>
        public bool TakeBacks { get; init; }

        /// <summary>Practice on the scene (<c>--practice</c>): no match.</summary>
        public bool Practice { get; init; }

        /// <summary>The drill to play (<c>--drill</c>: a name or a file), or null.</summary>
        public string? Drill { get; init; }

        /// <summary>The data folder (<c>--data</c>), or null for <see cref="Practice.DataFolder.Path"/>.</summary>
        public string? DataFolder { get; init; }

        /// <summary>Where practice saves and loads its position (<c>--save</c>), or null for the data folder's.</summary>
        public string? SavePath { get; init; }

        /// <summary>Called with the game once it is built, before its first frame (tests read the game through it).</summary>
        public Action<GameHost>? Started { get; init; }

        /// <summary>Open with the start menu (plain <c>play</c>: no scene, game, players, script, stats or record given).</summary>
        public bool StartMenu { get; init; }

        /// <summary>The start menu's settings file, or null for the user's (<see cref="GameSettings.DefaultPath"/>).</summary>
        public string? SettingsPath { get; init; }

        /// <summary>A game over the network (<c>host</c>, <c>join</c>): its scene, its match and the link to the peer; null for a game at this table.</summary>
        public OnlineGame? Online { get; init; }

        /// <summary>Where a game hosted from the start menu listens (every address, port <see cref="NetCommands.DefaultPort"/> by default; tests: loopback).</summary>
        public System.Net.IPEndPoint? HostAt { get; init; }
    }

    private static GameRules? ParseRules(string? name)
    {
        if (name is null)
        {
            return null;
        }
        return RuleNames.TryParseGame(name, out var rules)
            ? rules
            : throw new CliException($"--rules {name}: unknown game (expected {string.Join(", ", RuleNames.GameNames)})");
    }

    /// <summary>
    /// The match a scene is played as: the scene's rules (or <c>--rules</c>) between the players of
    /// <c>--players</c>; none when the scene names no rules, so practice scenes stay practice.
    /// </summary>
    public static MatchSetup? MatchFor(Scene scene, GameRules? rules, string? players)
    {
        ArgumentNullException.ThrowIfNull(scene);
        GameRules? game = rules ?? scene.PlayedAs;
        if (game is not { } g)
        {
            return players is null ? null : throw new CliException($"--players {players}: {scene.Path} names no rules; give --rules too");
        }
        // Without --players: a person against the computer, or two people where the computer does not play the game.
        string[] parts = (players ?? (Ruleset.For(g).HasComputerPlayer ? DefaultPlayers : "human,human")).Split(',');
        if (parts.Length != 2)
        {
            throw new CliException($"--players {players}: expected two players A,B (each human or computer:LEVEL)");
        }
        var seats = new Seat[2];
        for (int i = 0; i < 2; i++)
        {
            seats[i] = Seat.Parse(parts[i], i)
                ?? throw new CliException($"--players {players}: \"{parts[i]}\" is not a player (a name of 1-{Seat.MaxNameLength} characters, human, or computer:LEVEL with LEVEL 1-5)");
        }
        if (Session.SeatProblem(Ruleset.For(g), seats) is { } problem)
        {
            throw new CliException($"--players {players}: {problem}");
        }
        return new MatchSetup(g, Distinct(seats));
    }

    /// <summary>
    /// Two seats of one name (two computers of one level, "Computer L3") told apart on the
    /// scoreboard and in the rulings: "Computer L3 (1)" and "Computer L3 (2)".
    /// </summary>
    public static Seat[] Distinct(IReadOnlyList<Seat> seats)
    {
        ArgumentNullException.ThrowIfNull(seats);
        var named = seats.ToArray();
        if (named.Length == 2 && named[0].Name == named[1].Name)
        {
            named[0] = named[0] with { Name = $"{named[0].Name} (1)" };
            named[1] = named[1] with { Name = $"{named[1].Name} (2)" };
        }
        return named;
    }

    /// <summary>The scene <c>play --practice</c> practises on without a scene: a few balls, no rules.</summary>
    public const string PracticeScene = "assets/scenes/practice.json";

    /// <summary>The shipped practice scene, beside the executable.</summary>
    public static string FindPracticeScene() => AssetFolder.File(Path.GetRelativePath("assets", PracticeScene));

    private static PracticeSetup PracticeFor(Scene scene, Core.Practice.Drill? drill, string savePath, string dataFolder) =>
        new(savePath, drill, drill is null ? null : DrillRecords.Load(Path.Combine(dataFolder, DrillRecords.FileName), Console.Error), scene.Shot);

    private static string PracticeTitle(PracticeSetup practice) =>
        practice.Drill is { } d ? $"{PlatformWiring.WindowTitle}: drill, {d.Title}" : $"{PlatformWiring.WindowTitle}: practice";

    /// <summary>The players without <c>--players</c>: a person against the computer at level 3.</summary>
    public const string DefaultPlayers = "human,computer:3";

    /// <summary>The shipped scene for a game: <c>assets/scenes/RULES.json</c>.</summary>
    public static string FindRulesScene(GameRules rules) => AssetFolder.File($"scenes/{rules.ToName()}.json");

    /// <summary>
    /// The default scene, in the shipped assets beside the executable (<see cref="AssetFolder"/>),
    /// whatever the working folder.
    /// </summary>
    public static string FindDefaultScene() => AssetFolder.File(Path.GetRelativePath("assets", DefaultScene));
}
