using Billiards.App.Camera;
using Billiards.App.Input;
using Billiards.App.Nodes;
using Billiards.App.Platform;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.App.Game;

/// <summary>A seat at the table: a person, or the computer at a level 1-5.</summary>
/// <param name="Name">The name shown on the HUD.</param>
/// <param name="ComputerLevel">The computer's level, or null for a person.</param>
public sealed record MatchPlayer(string Name, int? ComputerLevel = null)
{
    /// <summary>True for a person.</summary>
    public bool IsHuman => ComputerLevel is null;

    /// <summary>Longest player name (characters).</summary>
    public const int MaxNameLength = 24;

    /// <summary>
    /// Parses a seat: <c>human</c> (named "Player N"), <c>computer:LEVEL</c> or <c>cpu:LEVEL</c>
    /// (level 1-5), or any other name, a person of that name; null when it is none of them
    /// (empty, too long, a control character, or a computer without a level 1-5).
    /// </summary>
    public static MatchPlayer? Parse(string text, int seat)
    {
        ArgumentNullException.ThrowIfNull(text);
        string name = text.Trim();
        string t = name.ToLowerInvariant();
        if (t == "human")
        {
            return new MatchPlayer($"Player {seat + 1}");
        }
        foreach (string prefix in (string[])["computer:", "cpu:"])
        {
            if (t.StartsWith(prefix, StringComparison.Ordinal))
            {
                return int.TryParse(t[prefix.Length..], out int level) && level is >= 1 and <= 5
                    ? new MatchPlayer($"Computer L{level}", level)
                    : null;
            }
        }
        return name.Length is > 0 and <= MaxNameLength && !name.Any(char.IsControl) ? new MatchPlayer(name) : null;
    }
}

/// <summary>
/// A match in the window, driving Core's <see cref="Match"/>: it never decides a rule. At every
/// strike it hands the match the shot with the shooter's call and placement, and the physics node
/// runs the simulation the match made for it; when the balls rest the match judges the shot and
/// applies the ruling (spots, reracks, ball in hand, the winner), and the node shows the table the
/// match keeps and gives the cue ball in hand in its region. A game played here replays like any
/// other (<see cref="Billiards.Core.Scenes.GameRecordFile"/>).
/// Keys: Left/Right aim (A/D or Shift fine; held keys repeat, faster the longer they are held), W/Q power, Space shoots, 1-5 choose an offered option,
/// O declares a push-out, C cycles the called pocket, B cycles the called ball (in snooker the nominated colour or free ball), X aims at the call, Enter rematch.
/// </summary>
public sealed class MatchNode : Node
{
    /// <summary>Coarse and fine keyboard aim steps (degrees).</summary>
    public const double AimStepDegrees = 1.0, FineAimStepDegrees = 0.1;

    /// <summary>Keyboard power step and limits (m/s).</summary>
    public const double PowerStep = 0.25, MinPower = 0.25, MaxPower = 8.0;

    private readonly GameRules _rules;
    private readonly Ruleset _ruleset;
    private readonly GameState _opening;
    private readonly List<Ruling> _rulings = [];
    private readonly List<(GameState, ShotSpec)> _shots = [];
    private PhysicsNode? _physics;
    private CueNode? _cue;
    private CameraNode? _camera;
    private TableGeometry? _geometry;
    private Match? _match;
    private GameSetup? _firstGame;
    private BallId? _calledBall;
    private Call? _adoptedCall;
    private bool _hasAdoptedCall;
    private PocketId? _calledPocket;
    private int _games;
    private readonly List<Match> _sessionGames = [];

    /// <summary>Creates a match of <paramref name="rules"/> between two players from <paramref name="opening"/>.</summary>
    public MatchNode(GameRules rules, IReadOnlyList<MatchPlayer> players, GameState? opening = null)
    {
        ArgumentNullException.ThrowIfNull(players);
        _rules = rules;
        _ruleset = Ruleset.For(rules);
        Players = players;
        // A scene's game block keeps the players' names it gives; one that names none (the
        // defaults), and a fresh game, take the seats' names (play --players).
        var seats = new PerPlayer<string>(players[0].Name, players[1].Name);
        _opening = opening is { } o && o.Rules == rules
            ? o.Players == GameState.DefaultPlayers ? o with { Players = seats } : o
            : new GameState(rules) { Players = seats };
        State = _opening;
    }

    /// <summary>The game now being played (Core's state machine; its record is the game record), or null before the node is ready.</summary>
    public Match? Game => _match;

    /// <summary>Every game of this session in play order, the current one last (a rematch or a new game from the menu adds one).</summary>
    public IReadOnlyList<Match> Games => _sessionGames;

    /// <summary>
    /// The games a record of the session holds (<c>play --record</c>): every game with a shot, in
    /// play order; a game begun but not played (the window closed on a rematch's rack) is left
    /// out, unless no game has a shot.
    /// </summary>
    public IReadOnlyList<Match> RecordedGames =>
        _sessionGames.Any(g => g.Shots.Count > 0) ? [.. _sessionGames.Where(g => g.Shots.Count > 0)] : [.. _sessionGames.Take(1)];

    /// <summary>The game's ruleset.</summary>
    public Ruleset Ruleset => _ruleset;

    /// <summary>The two players.</summary>
    public IReadOnlyList<MatchPlayer> Players { get; }

    /// <summary>The game being played.</summary>
    public GameRules Rules => _rules;

    /// <summary>The state of the game before the next shot.</summary>
    public GameState State { get; private set; }

    /// <summary>Every ruling of the match, in order.</summary>
    public IReadOnlyList<Ruling> Rulings => _rulings;

    /// <summary>The last ruling, or null before the first shot ends.</summary>
    public Ruling? LastRuling => _rulings.Count > 0 ? _rulings[^1] : null;

    /// <summary>The options the incoming player must choose from now (empty when none).</summary>
    public IReadOnlyList<RefereeOption> PendingOptions { get; private set; } = [];

    /// <summary>The message shown now (a ruling, a hint, a new game), kept until the next shot; or null.</summary>
    public string? Message { get; private set; }

    /// <summary>True once the referee ended the game.</summary>
    public bool IsOver { get; private set; }

    /// <summary>Seconds a game between two computers stays over before the next one starts by itself.</summary>
    public const double AutoRematchSeconds = 6;

    /// <summary>
    /// Seconds until the next game starts by itself (two computers at the table, nobody to press
    /// Enter), or null when a person decides.
    /// </summary>
    public double? RematchIn { get; private set; }

    /// <summary>The winner (0 or 1) of the game just ended, or null.</summary>
    public int? Winner { get; private set; }

    /// <summary>Games won by each player in this match.</summary>
    public PerPlayer<int> GamesWon { get; private set; }

    /// <summary>The keyboard power at the start (m/s), and where it comes back to after a power break.</summary>
    public const double DefaultPower = 3.0;

    /// <summary>The keyboard power (m/s).</summary>
    public double Power { get; private set; } = DefaultPower;

    /// <summary>
    /// The aim preview (first ball, ghost ball, object direction, easiest pocket), or null without
    /// a cue ball or while balls roll. Computed when asked, from the aim of the moment: keys that
    /// arrive in one frame see each other's effect as they would in separate frames.
    /// </summary>
    public AimPreview? Aim => _physics is { IsRolling: false, HasCueBall: true } physics && _cue is not null && _geometry is not null
        ? AimPreview.Compute(physics.Simulation.Balls, physics.Simulation.Ids, physics.Simulation.IndexOf(physics.CueBall), _cue.AimDirection, physics.BallRadius, _geometry.Pockets, physics.Table.Pockets)
        : null;

    /// <summary>Every shot struck in the match, in order: the state at the strike (with its call and placement) and the shot.</summary>
    public IReadOnlyList<(GameState Before, ShotSpec Shot)> Shots => _shots;

    /// <summary>True while the computer is to move: its shot, or its choice among a ruling's options (a script's waits wait for it).</summary>
    public bool IsComputerActing => !IsOver && !Players[State.Shooter].IsHuman;

    /// <summary>The seed of the planner's search and of the computer's error for the shot to come: the same game, the same decisions.</summary>
    /// <remarks>A shot taken back and played again draws new seeds (the computer plays it anew, with an error of its own).</remarks>
    public ulong ShotSeed(long stream) => Billiards.Core.Ai.PlannerRandom.Derive(MatchSeed, (_games * 10_000L) + State.Shot, stream + (TakeBackCount * 16L));

    /// <summary>
    /// True when the players allow take-backs (the start menu's setting, <c>play --take-backs</c>;
    /// off by default): <see cref="TakeBack"/> then puts the game back before the last shot.
    /// </summary>
    public bool TakeBacks { get; set; }

    /// <summary>Shots taken back in this match.</summary>
    public int TakeBackCount { get; private set; }

    /// <summary>Signal: a shot was taken back (a computer at work drops what it was doing).</summary>
    public event Action? TookBack;

    // The game before each shot of this game, newest last.
    private readonly List<(MatchSnapshot Game, GameState State, PerPlayer<int> GamesWon)> _beforeShots = [];

    /// <summary>True when <see cref="TakeBack"/> can act now: take-backs allowed, a shot of this game played, the balls at rest.</summary>
    public bool CanTakeBack => TakeBacks && _beforeShots.Count > 0 && _physics is { IsRolling: false };

    /// <summary>
    /// Takes the last shot back (whoever played it): the balls bit for bit where they were before it,
    /// the whole game state (Core's <see cref="Match.Restore"/>), the rulings and the games won as
    /// they stood; the shooter plays again. Against the computer it works both ways: a shot the
    /// computer played is taken back too, and the computer plays it again. False when take-backs
    /// are off, nothing is left to take back, or balls roll.
    /// </summary>
    public bool TakeBack()
    {
        if (!CanTakeBack || _match is null)
        {
            return false;
        }
        var (game, state, won) = _beforeShots[^1];
        _beforeShots.RemoveAt(_beforeShots.Count - 1);
        _match.Restore(game);
        int shots = game.Shots.Count;
        _rulings.RemoveRange(shots, _rulings.Count - shots);
        _shots.RemoveRange(shots, _shots.Count - shots);
        State = state with { Call = null, Placement = null };
        GamesWon = won;
        PendingOptions = [];
        IsOver = false;
        Winner = null;
        RematchIn = null;
        _calledBall = null;
        _calledPocket = null;
        _hasAdoptedCall = false;
        _adoptedCall = null;
        TakeBackCount++;
        _physics!.Load(_match.Layout());
        GiveHand(_match.BallInHand);
        Say($"Take-back: {State.ShooterName} plays again.");
        TookBack?.Invoke();
        return true;
    }

    /// <summary>The match's seed for the computer player (default 1).</summary>
    public ulong MatchSeed { get; init; } = 1;

    /// <summary>The cue's aim now (deg, from +x counter-clockwise).</summary>
    public double AimDegrees => _cue is null ? 0 : ViewMath.AimDegrees(_cue.AimDirection);

    /// <summary>Turns the cue to <paramref name="degrees"/> exactly (the camera's azimuth behind the cue ball).</summary>
    public void AimAt(double degrees)
    {
        if (_camera is null || _physics is null || _physics.IsRolling)
        {
            return;
        }
        CueAim.AimAt(_camera.Camera, _physics.CueBallPosition, degrees);
    }

    /// <summary>
    /// Takes a plan (the computer's, or a hint for a person): the cue ball placed where it says (with
    /// ball in hand), its call, its push-out, the power of its shot, and the aim turned to it.
    /// </summary>
    public void Adopt(Billiards.Core.Ai.Decision decision, bool exactCall)
    {
        ArgumentNullException.ThrowIfNull(decision);
        if (_physics is null || !CanShoot)
        {
            return;
        }
        if (decision.Place is { } place && _physics.BallInHand)
        {
            var old = _physics.CueBallPosition;
            if (_physics.TryPlaceCueBall(place) && _camera is not null)
            {
                _camera.Camera.Translate(_physics.CueBallPosition - old);
            }
        }
        _calledBall = decision.Call is { IsSafety: false } c ? c.Ball : null;
        _calledPocket = decision.Call is { IsSafety: false } c2 ? c2.Pocket : null;
        _adoptedCall = exactCall ? decision.Call : null;
        _hasAdoptedCall = exactCall;
        if (decision.PushOut && _ruleset.MayPushOut(State))
        {
            State = State with { PushOut = true };
        }
        if (!exactCall)
        {
            // A hint sets the person's power; the computer strikes its own shot and leaves the person's power alone.
            Power = Math.Clamp(decision.Shot.Speed, MinPower, MaxPower);
            _cue?.Take(decision.Shot);
        }
        AimAt(decision.Shot.AimDeg);
    }

    /// <summary>Shows what a hint suggests: the call, the speed and how often the planner saw it succeed.</summary>
    public void SayHint(Billiards.Core.Ai.Decision hint)
    {
        ArgumentNullException.ThrowIfNull(hint);
        Say(ComputerPlayerNode.HintLine(hint));
    }

    /// <summary>Calls a ball (a click on it): its easiest pocket until a pocket is called; in snooker it nominates the ball where the shooter may nominate it.</summary>
    public void CallBall(BallId ball)
    {
        if (CanShoot && (!NeedsNomination || _ruleset.MayCall(State, ball)))
        {
            _calledBall = ball;
            _calledPocket = null;
        }
    }

    /// <summary>Calls a pocket (a click on it) for the called ball, or for the aimed one.</summary>
    public void CallPocket(PocketId pocket)
    {
        if (CanShoot)
        {
            _calledBall ??= DefaultBall(Aim);
            _calledPocket = pocket;
        }
    }

    /// <summary>Strikes a shot the computer plays (its plan with its own error), with the call it adopted.</summary>
    public void StrikeAsComputer(ShotSpec shot)
    {
        if (CanShoot)
        {
            _physics!.Strike(_cue?.Playable(shot) ?? shot);
        }
    }

    /// <summary>
    /// The call the shooter makes now: the chosen ball (else the aimed one when it is a legal
    /// target, else the legal target nearest the cue ball) and the chosen pocket (else that
    /// ball's easiest pocket). The ruleset says which balls are legal: never the opponent's group.
    /// </summary>
    public Call? CurrentCall
    {
        get
        {
            var aim = Aim;
            var ball = _calledBall ?? DefaultBall(aim);
            if (ball is not { } b || PocketFor(b, aim) is not { } pocket || pocket == PocketId.None)
            {
                return null;
            }
            return new Call(b, pocket);
        }
    }

    /// <summary>True when the rules call this shot (<see cref="Ruleset.NeedsCall"/>).</summary>
    public bool NeedsCall => _ruleset.NeedsCall(State);

    /// <summary>True when the shooter nominates a ball without a pocket (snooker's colour after a red, a free ball: <see cref="Ruleset.Nominates"/>).</summary>
    public bool NeedsNomination => _ruleset.Nominates(State);

    /// <summary>
    /// The nomination the shooter makes now: the ball chosen (B, or a click), else the aimed ball,
    /// else the nearest ball, among those the shooter may nominate; null where nothing is nominated.
    /// </summary>
    public Call? CurrentNomination
    {
        get
        {
            if (!NeedsNomination || _physics is null)
            {
                return null;
            }
            var may = Nominatable();
            var aimed = Aim?.Ball;
            var ball = _calledBall is { } c && may.Contains(c) ? c
                : aimed is { } a && may.Contains(a) ? a
                : Nearest(_physics.CueBallPosition with { Z = 0 }, may);
            return ball is { } b ? Call.Nominate(b) : null;
        }
    }

    private List<BallId> Nominatable() => [.. _physics!.ObjectBallsOnTable().Where(b => _ruleset.MayCall(State, b)).OrderBy(b => b.Value)];

    /// <summary>True when the shooter may strike now: balls at rest, no option pending, the game on.</summary>
    public bool CanShoot => _physics is { IsRolling: false, HasCueBall: true } && PendingOptions.Count == 0 && !IsOver;

    /// <summary>The shooter's player.</summary>
    public MatchPlayer Shooter => Players[State.Shooter];

    /// <summary>Signal: the referee ruled on a shot.</summary>
    public event Action<Ruling>? Ruled;

    /// <summary>
    /// Signal: the game moved on and the shooter may play (a ruling with nothing to choose, a choice
    /// made, a new game). Raised at once, within the change, so that what reacts to it (the view
    /// turning to the ball on) has done so before the next input, however the frames fall: an
    /// input script plays the same game at any frame rate.
    /// </summary>
    public event Action? ShooterToPlay;

    /// <inheritdoc />
    protected override void Ready()
    {
        _physics = GetInTree<PhysicsNode>();
        _cue = FindInTree<CueNode>();
        _camera = FindInTree<CameraNode>();
        _geometry = TableGeometry.Build(_physics.Table, _physics.BallRadius);
        _physics.HandOnly = true;
        _physics.StrikeThrough = OnStrike;
        _physics.CameToRest += _ => OnRest();
        _firstGame = FirstGame(_physics);
        _match = new Match(_firstGame, _physics.CreateSimulation);
        _sessionGames.Add(_match);
        if (_physics.IsRolling && _physics.LastShot is { } opening)
        {
            // The scene's own shot is already on its way: the match plays it from the scene's
            // position with the game block's call.
            var sim = _match.Strike(new GameShot(opening, State.Call, _match.BallInHand == BallInHand.None ? null : _match.Balls[_ruleset.CueBall(State)], State.PushOut));
            _physics.ReplaceShot(sim);
        }
        else
        {
            LoadLayout(_match);
            GiveHand(_match.BallInHand);
        }
        Say(State.Shot == 0 ? $"{State.ShooterName} to break." : $"{State.ShooterName} to shoot.");
    }

    // The scene's game: its table, physics, rack seed and game block; its balls when they are
    // not the rack's (a position set up in the scene).
    private GameSetup FirstGame(PhysicsNode physics)
    {
        var scene = physics.Scene;
        var setup = new GameSetup(scene.Table, scene.Physics, scene.Rack?.Seed ?? 1, _opening with { Call = null, PushOut = false, Placement = null });
        var sim = physics.Simulation;
        var balls = new List<(BallId Id, Vec3 Position)>();
        for (int i = 0; i < sim.Ids.Count; i++)
        {
            if (!sim.Balls[i].IsPocketed)
            {
                balls.Add((sim.Ids[i], sim.Balls[i].Position));
            }
        }
        var rack = setup.Racked(0);
        bool racked = balls.Count == rack.Count && rack.All(b => balls.Contains(b));
        return racked ? setup : setup with { Position = balls };
    }

    /// <inheritdoc />
    protected override void Process(double dt)
    {
        if (IsOver && RematchIn is double left)
        {
            RematchIn = left - dt;
            if (RematchIn <= 0)
            {
                Rematch();
            }
        }
    }

    /// <inheritdoc />
    protected override bool Input(InputEvent e)
    {
        if (e is not KeyInput { Pressed: true } key)
        {
            return false;
        }
        if (IsComputerActing)
        {
            // The computer's turn: the person watches (the camera and system keys still work).
            return key.Key is >= Key.D1 and <= Key.D5 or Key.Space or Key.Left or Key.Right or Key.A or Key.D or Key.W or Key.Q or Key.O or Key.C or Key.B or Key.X;
        }
        switch (key.Key)
        {
            case >= Key.D1 and <= Key.D5 when (int)(key.Key - Key.D1) < PendingOptions.Count:
                Choose(PendingOptions[key.Key - Key.D1]);
                return true;
            case Key.Enter when IsOver:
                Rematch();
                return true;
            case Key.Space when CanShoot && _cue is not null:
                _physics!.Strike(_cue.MakeShot(Power));
                if (State.Shot == 0 && _ruleset.PowerBreak)
                {
                    // The break's power is the break's alone: the next shot does not start at 8 m/s.
                    Power = Math.Min(Power, DefaultPower);
                }
                return true;
            case Key.Left or Key.Right or Key.A or Key.D:
                Turn(key.Key switch
                {
                    Key.Left => key.Shift ? FineAimStepDegrees : AimStepDegrees,
                    Key.Right => key.Shift ? -FineAimStepDegrees : -AimStepDegrees,
                    Key.A => FineAimStepDegrees,
                    _ => -FineAimStepDegrees,
                });
                return true;
            case Key.W:
                Power = Math.Min(MaxPower, Power + PowerStep);
                return true;
            case Key.Q:
                Power = Math.Max(MinPower, Power - PowerStep);
                return true;
            case Key.O when CanShoot && _ruleset.MayPushOut(State):
                State = State with { PushOut = !State.PushOut };
                Say(State.PushOut ? $"{State.ShooterName} declares a push-out." : "Push-out withdrawn.");
                return true;
            case Key.C when CanShoot:
                CyclePocket();
                return true;
            case Key.B when CanShoot:
                CycleBall();
                return true;
            case Key.X when CanShoot:
                AimAtCall();
                return true;
            default:
                return false;
        }
    }

    /// <summary>Carries out the incoming player's choice among the ruling's options.</summary>
    /// <exception cref="ArgumentException">When the option is not offered now.</exception>
    public void Choose(RefereeOption option)
    {
        if (LastRuling is not { } ruling || !PendingOptions.Contains(option))
        {
            throw new ArgumentException($"\"{option.ToName()}\" is not offered now", nameof(option));
        }
        PendingOptions = [];
        _match!.Choose(option);
        State = _match.State;
        LoadLayout(_match);
        GiveHand(_match.BallInHand);
        Say(State.Shot == 0 ? $"Rerack: {State.ShooterName} breaks." : option switch
        {
            // Snooker's choices in words: who plays, and from what.
            RefereeOption.Play => $"{State.ShooterName} plays the balls as they lie{(State.FreeBall ? ", with a free ball" : "")}.",
            RefereeOption.PutBack => $"Put back: {State.ShooterName} plays again.",
            RefereeOption.Replace => $"The balls are replaced: {State.ShooterName} plays again.",
            _ => $"{option.ToName()}: {State.ShooterName} to shoot.",
        });
        ShooterToPlay?.Invoke();
    }

    /// <summary>A new game after the last one ended: the balls reracked, the other player breaks.</summary>
    public void Rematch()
    {
        if (!IsOver)
        {
            return;
        }
        _games++;
        NewGame("New game");
    }

    /// <summary>The game starts again (the pause menu): the balls reracked, the same player breaks; games won stay.</summary>
    public void Restart()
    {
        if (_physics is null || _physics.IsRolling)
        {
            return;
        }
        NewGame("Restart");
    }

    private void NewGame(string what)
    {
        int breaker = (_opening.Shooter + _games) % 2;
        IsOver = false;
        RematchIn = null;
        Winner = null;
        PendingOptions = [];
        _calledBall = null;
        _calledPocket = null;
        _beforeShots.Clear();
        State = new GameState(_rules) { Players = _opening.Players, Shooter = breaker, Target = _opening.Target };
        // Game g racks with the scene's seed + g.
        _match = new Match(_firstGame! with { Seed = _firstGame.Seed + _games, Start = State, Position = null }, _physics!.CreateSimulation);
        _sessionGames.Add(_match);
        LoadLayout(_match);
        GiveHand(_match.BallInHand);
        Say($"{what}: {State.ShooterName} breaks.");
        NewGameStarted?.Invoke();
        ShooterToPlay?.Invoke();
    }

    /// <summary>Signal: a new game was racked (a restart or a rematch): what was planned for the last table is void.</summary>
    public event Action? NewGameStarted;

    // The physics node asks for the shot's simulation: the match makes it from the balls at rest,
    // with the cue ball where the player placed it (ball in hand, the break from the kitchen).
    private Simulation OnStrike(ShotSpec shot)
    {
        _beforeShots.Add((_match!.Snapshot(), State, GamesWon));
        bool inHand = _match.BallInHand != BallInHand.None;
        var call = _hasAdoptedCall ? _adoptedCall : NeedsCall ? CurrentCall : NeedsNomination ? CurrentNomination : null;
        var sim = _match.Strike(new GameShot(shot, call, inHand ? _physics!.CueBallPosition : null, State.PushOut));
        _shots.Add((_match.RunningShotState!, shot));
        _hasAdoptedCall = false;
        _adoptedCall = null;
        Message = null;
        _calledBall = null;
        _calledPocket = null;
        return sim;
    }

    private void OnRest()
    {
        if (_match is not { IsShotRunning: true } match || _physics is null || IsOver)
        {
            return;
        }
        var played = match.Judge(_physics.Simulation);
        var ruling = played.Ruling;
        _rulings.Add(ruling);
        State = ruling.GameOver ? EndState(played.Before, ruling) : match.State;
        LoadLayout(match);
        Say(ruling.Message);
        if (ruling.GameOver)
        {
            IsOver = true;
            Winner = ruling.Winner;
            RematchIn = Players.Any(p => p.IsHuman) ? null : AutoRematchSeconds;
            if (ruling.Winner is int w)
            {
                GamesWon = GamesWon.With(w, GamesWon[w] + 1);
            }
            _physics.EndBallInHand();
        }
        else if (match.PendingOptions.Count > 0)
        {
            // The table waits as the shot left it until the incoming player chooses.
            PendingOptions = match.PendingOptions;
            _physics.EndBallInHand();
        }
        else
        {
            GiveHand(match.BallInHand);
        }
        Ruled?.Invoke(ruling);
        if (CanShoot)
        {
            ShooterToPlay?.Invoke();
        }
    }

    // A game that ended shows how it stood at the end (groups, fouls, score), not the next game's
    // blank state; with the score after the last shot (14.1's winning balls, snooker's black that
    // won the frame or a foul's penalty), as the referee's last message gives it.
    private static GameState EndState(GameState before, Ruling ruling)
    {
        return before with
        {
            Shot = before.Shot + 1,
            Call = null,
            Placement = null,
            PushOut = false,
            BallInHand = BallInHand.None,
            FreeBall = false,
            Score = ruling.Score,
        };
    }

    private void GiveHand(BallInHand hand)
    {
        if (hand == BallInHand.None)
        {
            _physics!.EndBallInHand();
        }
        else
        {
            _physics!.GiveBallInHand(hand.Region());
        }
    }


    private void Turn(double degrees)
    {
        if (_camera is null || _physics is null || _physics.IsRolling)
        {
            return;
        }
        CueAim.Turn(_camera.Camera, _physics.CueBallPosition, degrees);
    }

    // X: the cue aims at the ghost ball that sends the called ball (or, with no call, the nearest
    // ball) straight at its pocket's centre; geometry only, so cut shots still need the player's eye.
    private void AimAtCall()
    {
        if (_physics is null || _cue is null || _geometry is null)
        {
            return;
        }
        var sim = _physics.Simulation;
        var cue = _physics.CueBallPosition with { Z = 0 };
        var aim = Aim;
        var ball = _calledBall ?? DefaultBall(aim);
        if (ball is not { } b || PocketFor(b, aim) is not { } pocket)
        {
            return;
        }
        var target = sim.Balls[sim.IndexOf(b)].Position with { Z = 0 };
        Vec3? centre = null;
        foreach (var circle in _geometry.Pockets)
        {
            if (circle.Pocket == pocket.Index)
            {
                centre = circle.Centre with { Z = 0 };
            }
        }
        if (centre is not { } c)
        {
            return;
        }
        _calledBall = b;
        _calledPocket = pocket;
        var ghost = target - 2 * _physics.BallRadius * (c - target).Normalized();
        double want = ViewMath.AimDegrees(ghost - cue);
        double now = ViewMath.AimDegrees(_cue.AimDirection);
        double turn = Math.IEEERemainder(want - now, 360);
        Turn(turn);
        // The camera's eye is not exactly behind the ball after recentring: one more pass corrects the rest.
        Turn(Math.IEEERemainder(want - ViewMath.AimDegrees(_cue.AimDirection), 360));
    }

    // The pocket called for a ball: the one chosen with C, else the aimed ball's easiest pocket
    // along its line from the ghost ball, else (a ball chosen with B) the easiest pocket along the
    // line from the cue ball through it.
    private PocketId? PocketFor(BallId ball, AimPreview? aim)
    {
        if (_calledPocket is { } chosen)
        {
            return chosen;
        }
        if (aim is not null && aim.Ball == ball)
        {
            return aim.Pocket;
        }
        if (_physics is null || _geometry is null || _physics.Simulation.IndexOf(ball) is not (>= 0 and var i))
        {
            return null;
        }
        var target = _physics.Simulation.Balls[i].Position with { Z = 0 };
        var cue = _physics.CueBallPosition with { Z = 0 };
        return AimPreview.EasiestPocket(target, (target - cue).Normalized(), _geometry.Pockets, _geometry.Spec.Pockets);
    }

    // The aimed ball when the shooter may hit it first, else the nearest ball that they may.
    private BallId? DefaultBall(AimPreview? aim)
    {
        if (_physics is null)
        {
            return null;
        }
        var legal = _ruleset.LegalTargets(State, _physics!.ObjectBallsOnTable());
        return aim?.Ball is { } aimed && legal.Contains(aimed) ? aimed : Nearest(_physics.CueBallPosition with { Z = 0 }, legal);
    }

    // The table between shots, and the ball the next shooter strikes on it.
    private void LoadLayout(Match match)
    {
        _physics!.CueBall = match.Ruleset.CueBall(match.State);
        _physics.Load(match.Layout());
    }

    private BallId? Nearest(Vec3 from, IReadOnlyList<BallId>? among = null)
    {
        var sim = _physics!.Simulation;
        BallId? best = null;
        double bestDistance = double.PositiveInfinity;
        for (int i = 0; i < sim.Ids.Count; i++)
        {
            if (sim.Ids[i] == _physics.CueBall || sim.Balls[i].IsPocketed || (among is not null && !among.Contains(sim.Ids[i])))
            {
                continue;
            }
            double d = ((sim.Balls[i].Position with { Z = 0 }) - from).Length;
            if (d < bestDistance)
            {
                bestDistance = d;
                best = sim.Ids[i];
            }
        }
        return best;
    }

    private void CyclePocket()
    {
        var pockets = _physics?.Table.Pockets.Ids ?? [];
        if (pockets.Count == 0)
        {
            return;
        }
        var current = CurrentCall?.Pocket ?? _calledPocket ?? PocketId.None;
        int at = -1;
        for (int i = 0; i < pockets.Count; i++)
        {
            at = pockets[i] == current ? i : at;
        }
        _calledPocket = pockets[(at + 1) % pockets.Count];
        _calledBall ??= DefaultBall(Aim);
    }

    private void CycleBall()
    {
        if (_physics is null)
        {
            return;
        }
        // Nominating (snooker), B goes round the balls the shooter may nominate.
        var onTable = NeedsNomination ? Nominatable() : _physics!.ObjectBallsOnTable();
        if (onTable.Count == 0)
        {
            return;
        }
        var current = NeedsNomination ? CurrentNomination?.Ball : _calledBall ?? Aim?.Ball;
        int k = current is { } c ? onTable.IndexOf(c) : -1;
        _calledBall = onTable[(k + 1) % onTable.Count];
    }

    private void Say(string message) => Message = message;
}
