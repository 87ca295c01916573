using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.Core.Rules;

/// <summary>
/// The turn controller: a sitting at the table of one game's rules, game after game. It keeps what
/// the window, self-play, replays and a network peer would otherwise each keep: the games played
/// and the games won, the seats, the take-back timeline, the end state of a game that is over,
/// and the answer to "may this shot be struck now, from there?". Every shot, whoever makes it (the
/// keys, the mouse, the computer, a replay, a peer), goes through <see cref="Submit"/>, every
/// option through <see cref="Choose"/>; <see cref="Play"/> is the one strike, rest, judge and
/// choose loop that every headless caller runs.
/// </summary>
/// <remarks>
/// The session decides nothing of the game: the <see cref="Match"/> of each game applies its
/// ruleset's rulings. A window runs the struck simulation on its own clock and hands it back to
/// <see cref="Rest"/>; headless callers run it to rest at once. Both are the same steps, so a game
/// played either way replays bit for bit.
/// </remarks>
public sealed class Session
{
    private readonly Func<Scene, Simulation>? _createSimulation;
    private readonly GameSetup _first;
    private readonly GameState _opening;
    private readonly List<Match> _games = [];
    // The game before each shot of the current game, newest last.
    private readonly Timeline<(MatchSnapshot Game, PerPlayer<int> GamesWon)> _timeline = new();

    /// <summary>Seconds a game between two computers stays over before the next one starts by itself.</summary>
    public const double AutoRematchSeconds = 6;

    /// <summary>
    /// A session of <paramref name="first"/>'s game between <paramref name="seats"/>. A first game
    /// whose players are the defaults takes the seats' names.
    /// </summary>
    /// <param name="first">The first game.</param>
    /// <param name="seats">The two seats, player 0 first.</param>
    /// <param name="createSimulation">Makes each shot's simulation (<see cref="SimulationFactory.Create"/> by default).</param>
    /// <param name="opening">The first shot's state as a scene gives it (its call and push-out); null for the setup's start.</param>
    public Session(GameSetup first, IReadOnlyList<Seat> seats, Func<Scene, Simulation>? createSimulation = null, GameState? opening = null)
    {
        ArgumentNullException.ThrowIfNull(first);
        ArgumentNullException.ThrowIfNull(seats);
        if (seats.Count != 2)
        {
            throw new ArgumentException("a session has two seats", nameof(seats));
        }
        if (SeatProblem(first.Ruleset, seats) is { } problem)
        {
            throw new ArgumentException(problem, nameof(seats));
        }
        Seats = seats;
        _createSimulation = createSimulation;
        var names = new PerPlayer<string>(seats[0].Name, seats[1].Name);
        var start = first.Start.Players == GameState.DefaultPlayers ? first.Start with { Players = names } : first.Start;
        _first = first with { Start = start };
        _opening = opening is null ? start : opening with { Players = start.Players };
        NewMatch(_first);
    }

    /// <summary>Why <paramref name="seats"/> cannot sit at <paramref name="ruleset"/>'s game (a computer seat where the game has no computer player), or null.</summary>
    public static string? SeatProblem(Ruleset ruleset, IReadOnlyList<Seat> seats)
    {
        ArgumentNullException.ThrowIfNull(ruleset);
        ArgumentNullException.ThrowIfNull(seats);
        return !ruleset.HasComputerPlayer && seats.Any(s => s.Kind == SeatKind.Computer)
            ? $"the computer player does not play {ruleset.Name}: seat a person"
            : null;
    }

    // A session over a game already made (Match.Play's one shot): script seats, the game's own simulations.
    private Session(Match game)
    {
        Seats = Seat.Of(game.Setup.Start.Players, SeatKind.Script);
        _first = game.Setup;
        _opening = game.Setup.Start;
        Game = game;
        _games.Add(game);
    }

    /// <summary>A session that plays on <paramref name="game"/> as it stands, from script seats (a test's or a tool's shots).</summary>
    public static Session Over(Match game)
    {
        ArgumentNullException.ThrowIfNull(game);
        return new Session(game);
    }

    /// <summary>
    /// A session on a scene's table: its physics, its rack's seed and its game block (for
    /// <paramref name="rules"/>; another game's block is ignored), from the balls of
    /// <paramref name="atStart"/> when they are not the rack's (a position set up in the scene).
    /// </summary>
    public static Session OfScene(Scene scene, GameRules rules, IReadOnlyList<Seat> seats, Simulation atStart, Func<Scene, Simulation>? createSimulation = null)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(atStart);
        var opening = scene.Game is { } o && o.Rules == rules ? o : new GameState(rules);
        var setup = new GameSetup(scene.Table, scene.Physics, scene.Rack?.Seed ?? 1, opening with { Call = null, PushOut = false, Placement = null });
        var balls = new List<(BallId Id, Vec3 Position)>();
        for (int i = 0; i < atStart.Ids.Count; i++)
        {
            if (!atStart.Balls[i].IsPocketed)
            {
                balls.Add((atStart.Ids[i], atStart.Balls[i].Position));
            }
        }
        var rack = setup.Racked(0);
        bool racked = balls.Count == rack.Count && rack.All(b => balls.Contains(b));
        return new Session(racked ? setup : setup with { Position = new BallLayout(balls) }, seats, createSimulation, opening);
    }

    /// <summary>
    /// Practice on <paramref name="position"/>'s table and balls: the same timeline without a
    /// referee (<see cref="PracticeRuleset"/>), one person at the table, take-backs on. Every shot
    /// goes through <see cref="Submit"/> and <see cref="Rest"/> as in a game, and
    /// <see cref="TakeBack"/> puts the balls back bit for bit, shot by shot.
    /// </summary>
    /// <param name="position">The table, the physics and the balls to start from (its shot is not played).</param>
    /// <param name="createSimulation">Makes each shot's simulation (<see cref="SimulationFactory.Create"/> by default).</param>
    /// <param name="player">The name the table shows.</param>
    public static Session Practice(Scene position, Func<Scene, Simulation>? createSimulation = null, string player = "Practice")
    {
        ArgumentNullException.ThrowIfNull(position);
        var start = new GameState(PracticeRuleset.Practice) { Players = new(player, player), Shot = 1, BallInHand = BallInHand.None };
        var setup = new GameSetup(position.Table, position.Physics, 1, start) { Position = position.Layout };
        return new Session(setup, Seat.Of(start.Players, SeatKind.Person), createSimulation) { TakeBacks = true };
    }

    /// <summary>
    /// Practice: the balls were moved by hand (dragged, added, taken off, a position loaded): the
    /// game goes on from <paramref name="position"/>'s balls. The timeline keeps the shots before,
    /// so a take-back still puts back the table before the last shot.
    /// </summary>
    /// <exception cref="InvalidOperationException">In a game with a referee, or while a shot runs.</exception>
    public void Reposition(Scene position)
    {
        ArgumentNullException.ThrowIfNull(position);
        if (Ruleset is not PracticeRuleset || IsShotRunning)
        {
            throw new InvalidOperationException(IsShotRunning ? "a shot is still running" : "only practice moves balls by hand");
        }
        var now = Game.Snapshot();
        Game.Restore(new MatchSnapshot(now.Setup, now.State with { BallInHand = BallInHand.None }, position.Layout, now.Shots, now.Racks));
    }

    /// <summary>The two seats, player 0 first.</summary>
    public IReadOnlyList<Seat> Seats { get; }

    /// <summary>The game being played now (its record is the game record).</summary>
    public Match Game { get; private set; } = null!;

    /// <summary>Every game of the session in play order, the current one last.</summary>
    public IReadOnlyList<Match> Games => _games;

    /// <summary>
    /// The games a record of the session holds: every game with a shot, in play order; a game
    /// begun but not played (a rematch's rack) is left out, unless no game has a shot.
    /// </summary>
    public IReadOnlyList<Match> RecordedGames =>
        _games.Any(g => g.Shots.Count > 0) ? [.. _games.Where(g => g.Shots.Count > 0)] : [.. _games.Take(1)];

    /// <summary>Rematches so far (game g racks with the first game's seed + g).</summary>
    public int Rematches { get; private set; }

    /// <summary>The game's ruleset.</summary>
    public Ruleset Ruleset => Game.Ruleset;

    /// <summary>The game's rules.</summary>
    public GameRules Rules => Game.Setup.Rules;

    /// <summary>Games won by each player in this session.</summary>
    public PerPlayer<int> GamesWon { get; private set; }

    /// <summary>True once the referee ended the current game.</summary>
    public bool IsOver => Game.IsOver;

    /// <summary>The winner (0 or 1) of the game just ended, or null.</summary>
    public int? Winner => IsOver ? Game.LastRuling!.Winner : null;

    /// <summary>
    /// The game state before the next shot; after the game is over, how it stood at the end (the
    /// groups, the fouls, the score after the last shot), not a blank next game.
    /// </summary>
    public GameState State => IsOver ? EndState(Game.Shots[^1].Before, Game.LastRuling!) : Game.State;

    /// <summary>The seat of the player to shoot (or to choose) now.</summary>
    public Seat Shooter => Seats[State.Shooter];

    /// <summary>True while the computer is to move: its shot, or its choice among a ruling's options.</summary>
    public bool IsComputerActing => !IsOver && Shooter.Kind == SeatKind.Computer;

    /// <summary>The last ruling of the current game, or null before its first shot is judged.</summary>
    public Ruling? LastRuling => Game.LastRuling;

    /// <summary>Every ruling of the session, in order.</summary>
    public IReadOnlyList<Ruling> Rulings => [.. _games.SelectMany(g => g.Shots.Select(s => s.Ruling))];

    /// <summary>Every shot struck in the session, in order (the running one last): the state at the strike (with its call and placement) and the shot.</summary>
    public IReadOnlyList<(GameState Before, Cue.ShotSpec Shot)> Shots
    {
        get
        {
            var shots = _games.SelectMany(g => g.Shots.Select(s => (s.Before, s.Input.Shot))).ToList();
            if (Game.RunningShot is { } running)
            {
                shots.Add((running.Before, running.Input.Shot));
            }
            return shots;
        }
    }

    /// <summary>The options the incoming player must choose from now (empty when none).</summary>
    public IReadOnlyList<RefereeOption> PendingOptions => Game.PendingOptions;

    /// <summary>Where the next shooter may place the cue ball.</summary>
    public BallInHand BallInHand => Game.BallInHand;

    /// <summary>True from <see cref="Submit"/> until <see cref="Rest"/>.</summary>
    public bool IsShotRunning => Game.IsShotRunning;

    /// <summary>The last thing said at the table (a ruling, a refusal, a new game, a hint), kept until the next shot; or null.</summary>
    public string? Message { get; private set; }

    /// <summary>
    /// Counts every change of the game's course (a strike, a ruling, a choice, a take-back, a new
    /// game): a plan made at one count is for that table only.
    /// </summary>
    public long Turn { get; private set; }

    /// <summary>True when the players allow take-backs (off by default); the timeline keeps the shots struck while it is on.</summary>
    public bool TakeBacks { get; set; }

    /// <summary>Shots taken back in this session.</summary>
    public int TakeBackCount { get; private set; }

    /// <summary>True when <see cref="TakeBack"/> can act now: take-backs allowed, a shot of this game played, no shot running.</summary>
    public bool CanTakeBack => TakeBacks && _timeline.Count > 0 && !IsShotRunning;

    /// <summary>Seconds until the next game starts by itself (two computers at the table), or null when a person decides.</summary>
    public double? RematchIn { get; private set; }

    /// <summary>
    /// Why the game waits for the other end of a network (no player joined yet, the connection
    /// lost, the game so far on its way), or null. While it is set no one at this table strikes or
    /// chooses; the remote seat's moves that came are still carried out.
    /// </summary>
    public string? Held { get; set; }

    /// <summary>The winner (0 or 1) of a game the other player forfeited (a network peer that did not come back), or null; after it no shot is struck.</summary>
    public int? ForfeitWinner { get; private set; }

    /// <summary>True while a player elsewhere is to move: their shot, or their choice among a ruling's options.</summary>
    public bool IsRemoteActing => !IsOver && ForfeitWinner is null && Shooter.Kind == SeatKind.Remote;

    /// <summary>True while the game is on but held for the network (<see cref="Held"/>) or ended by forfeit.</summary>
    public bool IsHeld => !IsOver && (Held is not null || ForfeitWinner is not null);

    /// <summary>Ends the game by forfeit: <paramref name="winner"/> wins, <paramref name="message"/> is said, and no shot is struck any more.</summary>
    public void Forfeit(int winner, string message)
    {
        ForfeitWinner = winner;
        Message = message;
        Turn++;
    }

    /// <summary>
    /// Takes another game's state whole (a network host's game after a mismatch): the balls, the
    /// game state and the shots as <paramref name="game"/> has them; the table is replaced.
    /// </summary>
    public void Restore(MatchSnapshot game)
    {
        ArgumentNullException.ThrowIfNull(game);
        Game.Restore(game);
        Turn++;
        TableReplaced?.Invoke();
    }

    /// <summary>Signal: a shot was accepted by <see cref="Submit"/>, with where it came from (a network sends the local seat's).</summary>
    public event Action<GameShot, SeatKind>? Submitted;

    /// <summary>Signal: an option was chosen (<see cref="Choose"/>).</summary>
    public event Action<RefereeOption>? Chosen;

    /// <summary>Signal: the referee ruled on a shot.</summary>
    public event Action<Ruling>? Ruled;

    /// <summary>Signal: the game moved on and the shooter may play (a ruling with nothing to choose, a choice made, a new game, a take-back).</summary>
    public event Action? ShooterToPlay;

    /// <summary>Signal: the table was replaced by another (a take-back, a choice carried out, a restart, a new game): a plan for the old one is void.</summary>
    public event Action? TableReplaced;

    /// <summary>Says <paramref name="message"/> at the table (a hint, a push-out declared).</summary>
    public void Say(string message) => Message = message;

    /// <summary>
    /// Why a shot from <paramref name="source"/> may not be struck now, in one line for the player,
    /// or null when it may: the game is on, no shot runs, no option is pending, and it is the
    /// shooter's seat that plays it.
    /// </summary>
    public string? WhyNot(SeatKind source)
    {
        if (IsOver)
        {
            return "The game is over: no more shots.";
        }
        if (ForfeitWinner is not null)
        {
            return "The game ended by forfeit: no more shots.";
        }
        if (IsShotRunning)
        {
            return "The balls are still rolling.";
        }
        if (PendingOptions.Count > 0)
        {
            return $"{State.ShooterName} must choose an option first: {string.Join(", ", PendingOptions.Select(Ruleset.WordOf))}.";
        }
        return Shooter.Accepts(source) ? null : $"It is {State.ShooterName}'s turn.";
    }

    /// <summary>True when a shot from <paramref name="source"/> may be struck now (<see cref="WhyNot"/>).</summary>
    public bool MayStrike(SeatKind source) => WhyNot(source) is null;

    /// <summary>
    /// The one entry for a shot: when it may be struck now (<see cref="WhyNot"/>), keeps the game
    /// for a take-back, strikes it (<see cref="Match.Strike"/>) and returns the running shot for
    /// the caller to run to rest and hand to <see cref="Rest"/>; else says why not and returns null.
    /// </summary>
    public Simulation? Submit(GameShot shot, SeatKind source)
    {
        ArgumentNullException.ThrowIfNull(shot);
        if (WhyNot(source) is { } refusal)
        {
            Message = refusal;
            return null;
        }
        // The timeline is kept where take-backs are allowed (a headless game never takes one back).
        var snapshot = TakeBacks ? Game.Snapshot() : null;
        var sim = Game.Strike(shot);
        if (snapshot is not null)
        {
            _timeline.Push((snapshot, GamesWon));
        }
        Message = null;
        Turn++;
        Submitted?.Invoke(shot, source);
        return sim;
    }

    /// <summary>
    /// Practice: a person's stroke from <paramref name="position"/>'s balls as they lie now, moved
    /// by hand or not (<see cref="Reposition"/>), through the one entry (<see cref="Submit"/>).
    /// </summary>
    /// <returns>The running shot, or null when it may not be struck now.</returns>
    /// <exception cref="InvalidOperationException">In a game with a referee, or while a shot runs.</exception>
    public Simulation? StrikeFrom(Scene position, ShotSpec shot)
    {
        Reposition(position);
        return Submit(new GameShot(shot), SeatKind.Person);
    }

    /// <summary>
    /// Practice: <see cref="Rest"/>, and true when the shot left the cue ball in hand (it dropped),
    /// for the table to bring it back.
    /// </summary>
    public bool RestWithCueBallInHand(Simulation simulation) => Rest(simulation) is not null && BallInHand != BallInHand.None;

    /// <summary>
    /// Judges the running shot, now at rest in <paramref name="simulation"/>, and applies the
    /// ruling: the games won, the rematch clock of two computers, the ruling's words. Null when no
    /// shot runs.
    /// </summary>
    public MatchShot? Rest(Simulation simulation)
    {
        if (!IsShotRunning)
        {
            return null;
        }
        var played = Game.Judge(simulation);
        var ruling = played.Ruling;
        Message = ruling.Message;
        Turn++;
        if (ruling.GameOver)
        {
            RematchIn = Seats.Any(s => s.IsHuman) ? null : AutoRematchSeconds;
            if (ruling.Winner is int w)
            {
                GamesWon = GamesWon.With(w, GamesWon[w] + 1);
            }
        }
        Ruled?.Invoke(ruling);
        if (!IsOver && PendingOptions.Count == 0)
        {
            ShooterToPlay?.Invoke();
        }
        return played;
    }

    /// <summary>Carries out the incoming player's choice among the last ruling's options.</summary>
    /// <exception cref="ArgumentException">When the option is not offered now.</exception>
    public void Choose(RefereeOption option)
    {
        Game.Choose(option);
        Turn++;
        TableReplaced?.Invoke();
        var state = State;
        Message = state.Shot == 0 ? $"Rerack: {state.ShooterName} breaks." : Ruleset.ChoiceMessage(option, state);
        Chosen?.Invoke(option);
        ShooterToPlay?.Invoke();
    }

    /// <summary>
    /// The one strike, rest, judge and choose loop: submits <paramref name="shot"/> from
    /// <paramref name="source"/>, runs it to rest at once (<see cref="Match.RunToRest"/>), judges it,
    /// and when the ruling offers options and the shot chose none, takes
    /// <paramref name="choose"/>'s choice (without one the first option; a null choice leaves the
    /// options pending). <paramref name="struck"/>
    /// sees the shot's simulation between the strike and the run (a replay keeps its start).
    /// </summary>
    /// <exception cref="InvalidOperationException">When the shot may not be struck now (<see cref="WhyNot"/>).</exception>
    public MatchShot Play(GameShot shot, SeatKind source, Func<MatchShot, RefereeOption?>? choose = null, Action<Simulation>? struck = null)
    {
        var sim = Submit(shot, source) ?? throw new InvalidOperationException(Message);
        struck?.Invoke(sim);
        Match.RunToRest(sim);
        var played = Rest(sim)!;
        if (PendingOptions.Count > 0 && (choose is null ? PendingOptions[0] : choose(played)) is { } option)
        {
            Choose(option);
            return Game.Shots[^1];
        }
        return played;
    }

    /// <summary>
    /// Takes the last shot back (whoever played it): the balls bit for bit where they were before
    /// it, the game state and the games won as they stood; the shooter plays again. False when
    /// take-backs are off, nothing is left to take back, or a shot runs.
    /// </summary>
    public bool TakeBack()
    {
        if (!CanTakeBack || !_timeline.TryTakeBack(out var before))
        {
            return false;
        }
        var (game, won) = before;
        Game.Restore(game);
        GamesWon = won;
        RematchIn = null;
        TakeBackCount++;
        Turn++;
        Message = $"Take-back: {State.ShooterName} plays again.";
        TableReplaced?.Invoke();
        return true;
    }

    /// <summary>Counts down the rematch of two computers; starts the next game when it is due.</summary>
    public void Tick(double seconds)
    {
        if (IsOver && RematchIn is double left)
        {
            RematchIn = left - seconds;
            if (RematchIn <= 0)
            {
                Rematch();
            }
        }
    }

    /// <summary>A new game after the last one ended: the balls reracked, the other player breaks. False while the game is on.</summary>
    public bool Rematch()
    {
        if (!IsOver)
        {
            return false;
        }
        Rematches++;
        NewGame("New game");
        return true;
    }

    /// <summary>The game starts again: the balls reracked, the same player breaks; games won stay. False while a shot runs.</summary>
    public bool Restart()
    {
        if (IsShotRunning)
        {
            return false;
        }
        NewGame("Restart");
        return true;
    }

    /// <summary>
    /// The seed of the planner's search and of the computer's error for the shot to come, from
    /// <paramref name="matchSeed"/>: the same game, the same decisions; a shot taken back and
    /// played again draws new seeds.
    /// </summary>
    public ulong ShotSeed(ulong matchSeed, long stream) =>
        Ai.PlannerRandom.Derive(matchSeed, (Rematches * 10_000L) + State.Shot, stream + (TakeBackCount * 16L));

    private void NewGame(string what)
    {
        int breaker = (_opening.Shooter + Rematches) % 2;
        var start = new GameState(_first.Rules) { Players = _opening.Players, Shooter = breaker, Target = _opening.Target };
        // Game g racks with the first game's seed + g.
        NewMatch(_first with { Seed = _first.Seed + Rematches, Start = start, Position = null });
        Message = $"{what}: {State.ShooterName} breaks.";
        TableReplaced?.Invoke();
        ShooterToPlay?.Invoke();
    }

    private void NewMatch(GameSetup setup)
    {
        Game = new Match(setup, _createSimulation);
        _games.Add(Game);
        _timeline.Clear();
        RematchIn = null;
        Turn++;
        Message = Game.State.Shot == 0 ? $"{Game.State.ShooterName} to break." : $"{Game.State.ShooterName} to shoot.";
    }

    /// <summary>The first shot of a scene's own: struck from the scene's position with its game block's call and push-out.</summary>
    public Simulation? SubmitOpening(Cue.ShotSpec shot)
    {
        ArgumentNullException.ThrowIfNull(shot);
        var place = BallInHand == BallInHand.None ? (Vec3?)null : Game.Balls[Ruleset.CueBall(State)];
        string? said = Message;
        var sim = Submit(new GameShot(shot, _opening.Call, place, _opening.PushOut), Shooter.Kind);
        Message = sim is null ? Message : said;
        return sim;
    }

    // A game that ended shows how it stood at the end, with the score after the last shot.
    private static GameState EndState(GameState before, Ruling ruling) => before with
    {
        Shot = before.Shot + 1,
        Call = null,
        Placement = null,
        PushOut = false,
        BallInHand = BallInHand.None,
        Part = before.Part?.AtEnd,
        Score = ruling.Score,
    };
}
