using Billiards.App.Camera;
using Billiards.App.Input;
using Billiards.App.Input.Modes;
using Billiards.App.Nodes;
using Billiards.App.Platform;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.App.Game;

/// <summary>
/// A match in the window: the call, the aim and the view over Core's <see cref="Core.Rules.Session"/>,
/// which keeps the whole game (the games and games won, the seats, the take-back timeline, the end
/// state) and answers whether a shot may be struck now. The node keeps no game state: it composes
/// the shot (the call, the push-out declared, the power, the aim), hands every strike to the
/// session (<see cref="Core.Rules.Session.Submit"/>, which may refuse it with a message), shows the
/// table the session's match keeps and gives the cue ball in hand in its region.
/// Keys: Left/Right aim (A/D or Shift fine; held keys repeat, faster the longer they are held), W/Q power, Space shoots, 1-5 choose an offered option,
/// O declares a push-out, C cycles the called pocket, B cycles the called ball (in snooker the nominated colour or free ball), X aims at the call, Enter rematch.
/// </summary>
public sealed class MatchNode : Node
{
    /// <summary>Coarse and fine keyboard aim steps (degrees).</summary>
    public const double AimStepDegrees = 1.0, FineAimStepDegrees = 0.1;

    /// <summary>Keyboard power step and limits (m/s).</summary>
    public const double PowerStep = 0.25, MinPower = 0.25, MaxPower = 8.0;

    /// <summary>The keyboard power at the start (m/s), and where it comes back to after a power break.</summary>
    public const double DefaultPower = 3.0;

    private readonly ShotCall _call;
    private PhysicsNode? _physics;
    private CueNode? _cue;
    private CameraNode? _camera;
    private Call? _adoptedCall;
    private bool _hasAdoptedCall;
    private bool _computerStrikes;
    private GameShot? _peerShot;

    /// <summary>A match in the window of <paramref name="session"/>.</summary>
    public MatchNode(Session session)
    {
        ArgumentNullException.ThrowIfNull(session);
        Session = session;
        _call = new ShotCall(this);
        // Subscribed first: the table is shown as the session left it before anyone else hears of it.
        session.Ruled += _ => ShowTable();
        session.TableReplaced += ShowTable;
    }

    /// <summary>The turn controller: every game of this sitting, its state and its timeline.</summary>
    public Session Session { get; }

    /// <summary>The game now being played (Core's state machine; its record is the game record).</summary>
    public Match Game => Session.Game;

    /// <summary>The game's ruleset.</summary>
    public Ruleset Ruleset => Session.Ruleset;

    /// <summary>The two seats.</summary>
    public IReadOnlyList<Seat> Players => Session.Seats;

    /// <summary>The session's game state before the next shot (<see cref="Session.State"/>).</summary>
    public GameState State => Session.State;

    /// <summary>The options the incoming player must choose from now (empty when none).</summary>
    public IReadOnlyList<RefereeOption> PendingOptions => Session.PendingOptions;

    /// <summary>The message shown now (<see cref="Session.Message"/>).</summary>
    public string? Message => Session.Message;

    /// <summary>True once the referee ended the game.</summary>
    public bool IsOver => Session.IsOver;

    /// <summary>Games won by each player in this sitting.</summary>
    public PerPlayer<int> GamesWon => Session.GamesWon;

    /// <summary>True while the computer is to move.</summary>
    public bool IsComputerActing => Session.IsComputerActing;

    /// <summary>True while the player at the other end of the network is to move (their shot or their choice).</summary>
    public bool IsPeerActing => !IsOver && !Forfeited && Session.Shooter.Kind == SeatKind.Remote;

    /// <summary>
    /// Why the game waits for the network (no player joined yet, the connection lost), or null:
    /// while it is set no one at this table may strike or choose.
    /// </summary>
    public string? Held { get; set; }

    /// <summary>True once a networked game ended by forfeit (the peer did not come back): no more shots.</summary>
    public bool Forfeited { get; set; }

    /// <summary>True for a game over the network: no take-back, restart or rematch (the other side would not follow).</summary>
    public bool Networked { get; set; }

    /// <summary>True while the person at this table only watches: the computer's or the peer's move, or a game held by the network.</summary>
    public bool IsWatching => IsComputerActing || IsPeerActing || (!IsOver && !Forfeited && Held is not null);

    /// <summary>True when the players allow take-backs (<see cref="Session.TakeBacks"/>).</summary>
    public bool TakeBacks { get => Session.TakeBacks; set => Session.TakeBacks = value; }

    /// <summary>The keyboard power (m/s).</summary>
    public double Power { get; private set; } = DefaultPower;

    /// <summary>True when the shooter declared a push-out for the shot being composed.</summary>
    public bool PushOut { get; private set; }

    /// <summary>The match's seed for the computer player (default 1).</summary>
    public ulong MatchSeed { get; init; } = 1;

    /// <summary>The seed of the planner's search and of the computer's error for the shot to come (<see cref="Session.ShotSeed"/>).</summary>
    public ulong ShotSeed(long stream) => Session.ShotSeed(MatchSeed, stream);

    /// <summary>True when the shooter may strike now: balls at rest, a cue ball, and the session's yes (no option pending, the game on).</summary>
    public bool CanShoot => _physics is { IsRolling: false, HasCueBall: true } && !IsOver && !Forfeited && Held is null && PendingOptions.Count == 0;

    /// <summary>True when <see cref="TakeBack"/> can act now.</summary>
    public bool CanTakeBack => !Networked && Session.CanTakeBack && _physics is { IsRolling: false };

    /// <summary>Takes the last shot back (<see cref="Session.TakeBack"/>); false while balls roll or when the session refuses.</summary>
    public bool TakeBack() => CanTakeBack && Session.TakeBack();

    /// <summary>Signal: the referee ruled on a shot (after the table shows the ruling).</summary>
    public event Action<Ruling>? Ruled { add => Session.Ruled += value; remove => Session.Ruled -= value; }

    /// <summary>Signal: the game moved on and the shooter may play; raised within the change, so the view has turned before the next input.</summary>
    public event Action? ShooterToPlay { add => Session.ShooterToPlay += value; remove => Session.ShooterToPlay -= value; }

    /// <summary>The aim preview of the moment, or null without a cue ball or while balls roll.</summary>
    public AimPreview? Aim => _physics is { IsRolling: false, HasCueBall: true } physics && _cue is not null && _call.Geometry is { } geometry
        ? AimPreview.Compute(physics.Simulation.Balls, physics.Simulation.Ids, physics.Simulation.IndexOf(physics.CueBall), _cue.AimDirection, physics.BallRadius, geometry.Pockets, physics.Table.Pockets)
        : null;

    /// <summary>The cue's aim now (deg, from +x counter-clockwise).</summary>
    public double AimDegrees => _cue is null ? 0 : ViewMath.AimDegrees(_cue.AimDirection);

    /// <summary>The call the shooter makes now (<see cref="ShotCall.CurrentCall"/>).</summary>
    public Call? CurrentCall => _call.CurrentCall;

    /// <summary>The nomination the shooter makes now (<see cref="ShotCall.CurrentNomination"/>).</summary>
    public Call? CurrentNomination => _call.CurrentNomination;

    /// <summary>True when the rules call this shot.</summary>
    public bool NeedsCall => Ruleset.NeedsCall(State);

    /// <summary>True when the shooter nominates a ball without a pocket.</summary>
    public bool NeedsNomination => Ruleset.Nominates(State);

    /// <summary>The call being picked for the next shot (B, C, a click, a plan's).</summary>
    public ShotCall Call => _call;

    /// <summary>Turns the cue to <paramref name="degrees"/> exactly (the camera's azimuth behind the cue ball).</summary>
    public void AimAt(double degrees)
    {
        if (_camera is not null && _physics is { IsRolling: false })
        {
            CueAim.AimAt(_camera.Camera, _physics.CueBallPosition, degrees);
        }
    }

    /// <summary>Turns the cue by <paramref name="degrees"/>.</summary>
    internal void Turn(double degrees)
    {
        if (_camera is not null && _physics is { IsRolling: false })
        {
            CueAim.Turn(_camera.Camera, _physics.CueBallPosition, degrees);
        }
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
        _call.Take(decision.Call);
        _adoptedCall = exactCall ? decision.Call : null;
        _hasAdoptedCall = exactCall;
        PushOut |= decision.PushOut && Ruleset.MayPushOut(State);
        if (!exactCall)
        {
            // A hint sets the person's power; the computer strikes its own shot and leaves the person's power alone.
            Power = Math.Clamp(decision.Shot.Speed, MinPower, MaxPower);
            _cue?.Take(decision.Shot);
        }
        AimAt(decision.Shot.AimDeg);
    }

    /// <summary>Strikes a shot the computer plays (its plan with its own error), with the call it adopted; the session refuses it when it is not the computer's turn.</summary>
    public void StrikeAsComputer(ShotSpec shot)
    {
        if (CanShoot)
        {
            _computerStrikes = true;
            _physics!.Strike(_cue?.Playable(shot) ?? shot);
            _computerStrikes = false;
        }
    }

    /// <summary>
    /// Carries out the incoming player's choice at this table (<see cref="Session.Choose"/>);
    /// ignored while the peer chooses or the network holds the game.
    /// </summary>
    /// <exception cref="ArgumentException">When the option is not offered now.</exception>
    public void Choose(RefereeOption option)
    {
        if (IsPeerActing || Forfeited || Held is not null)
        {
            return;
        }
        Session.Choose(option);
        Chose?.Invoke(option);
    }

    /// <summary>Carries out the peer's choice, which came over the network (the session checks it is offered).</summary>
    /// <exception cref="ArgumentException">When the option is not offered now.</exception>
    public void ChooseAsPeer(RefereeOption option) => Session.Choose(option);

    /// <summary>Signal: a shot struck at this table (by the keys, the mouse or the computer) was accepted by the session.</summary>
    public event Action<GameShot>? Struck;

    /// <summary>Signal: an option was chosen at this table.</summary>
    public event Action<RefereeOption>? Chose;

    /// <summary>
    /// Strikes the peer's shot exactly as it came (its placement, call and push-out); the session
    /// refuses it unless the remote seat is to play.
    /// </summary>
    public bool StrikeAsPeer(GameShot shot)
    {
        ArgumentNullException.ThrowIfNull(shot);
        if (_physics is not { IsRolling: false, HasCueBall: true } physics || IsOver || Forfeited || PendingOptions.Count > 0)
        {
            return false;
        }
        ShowPeerPlacement(shot.Place);
        _peerShot = shot;
        try
        {
            physics.Strike(shot.Shot);
        }
        finally
        {
            _peerShot = null;
        }
        return physics.IsRolling;
    }

    /// <summary>Shows the peer's cue ball where they placed it (ball in hand), before their stroke.</summary>
    public void ShowPeerPlacement(Billiards.Core.Mathematics.Vec3? place)
    {
        if (place is not { } p || _physics is null || Session.BallInHand == BallInHand.None)
        {
            return;
        }
        var old = _physics.CueBallPosition;
        _physics.GiveBallInHand(Session.BallInHand.Region());
        if (_physics.TryPlaceCueBall(p) && _camera is not null)
        {
            _camera.Camera.Translate(_physics.CueBallPosition - old);
        }
        _physics.EndBallInHand();
    }

    /// <summary>Shows the table as the session's game stands (after the host's game was taken whole).</summary>
    public void Reload() => ShowTable();

    /// <summary>A new game after the last one ended (<see cref="Session.Rematch"/>); not over the network.</summary>
    public void Rematch()
    {
        if (!Networked)
        {
            Session.Rematch();
        }
    }

    /// <summary>The game starts again (the pause menu), while no ball rolls (<see cref="Session.Restart"/>); not over the network.</summary>
    public void Restart()
    {
        if (_physics is { IsRolling: false } && !Networked)
        {
            Session.Restart();
        }
    }

    /// <inheritdoc />
    protected override void Ready()
    {
        _physics = GetInTree<PhysicsNode>();
        _cue = FindInTree<CueNode>();
        _camera = FindInTree<CameraNode>();
        _call.Ready(_physics);
        _physics.HandOnly = true;
        _physics.StrikeThrough = OnStrike;
        _physics.CameToRest += _ => Session.Rest(_physics.Simulation);
        if (_physics.IsRolling && _physics.LastShot is { } opening && Session.SubmitOpening(opening) is { } sim)
        {
            // The scene's own shot is already on its way: the session plays it from the scene's position.
            _physics.ReplaceShot(sim);
        }
        else
        {
            ShowTable();
        }
    }

    /// <inheritdoc />
    protected override void Process(double dt) => Session.Tick(dt);

    /// <inheritdoc />
    protected override bool Input(InputEvent e)
    {
        if (e is not KeyInput { Pressed: true } key)
        {
            return false;
        }
        if (IsWatching)
        {
            // The computer's or the peer's turn: the person watches (the camera and system keys still work).
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
                bool power = State.Shot == 0 && Ruleset.PowerBreak;
                _physics!.Strike(_cue.MakeShot(Power));
                if (power)
                {
                    // The break's power is the break's alone: the next shot does not start at 8 m/s.
                    Power = Math.Min(Power, DefaultPower);
                }
                return true;
            // In move mode (ball in hand) the arrows nudge the cue ball (InputModeNode), A and D still aim.
            case Key.Left or Key.Right or Key.A or Key.D when !(key.Key is Key.Left or Key.Right && FindInTree<InputModeNode>()?.Mode == InputMode.Move):
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
            case Key.O when CanShoot && Ruleset.MayPushOut(State):
                PushOut = !PushOut;
                Session.Say(PushOut ? $"{State.ShooterName} declares a push-out." : "Push-out withdrawn.");
                return true;
            case Key.C when CanShoot:
                _call.CyclePocket();
                return true;
            case Key.B when CanShoot:
                _call.CycleBall();
                return true;
            case Key.X when CanShoot:
                _call.AimAtCall();
                return true;
            default:
                return false;
        }
    }

    // Every strike in the window (Space, the mouse, the computer) arrives here: the session says
    // whether it may be struck now and makes its simulation from the balls at rest.
    private Core.Physics.Simulation? OnStrike(ShotSpec shot)
    {
        if (_peerShot is { } peer)
        {
            // The peer's shot as it came: the session checks the seat, the placement and the call.
            var struck = Session.Submit(peer with { Shot = shot }, SeatKind.Remote);
            if (struck is not null)
            {
                ResetShot();
            }
            return struck;
        }
        if (Held is not null || Forfeited)
        {
            return null;
        }
        bool inHand = Session.BallInHand != BallInHand.None;
        var call = _hasAdoptedCall ? _adoptedCall : NeedsCall ? CurrentCall : NeedsNomination ? CurrentNomination : null;
        var source = _computerStrikes ? SeatKind.Computer : SeatKind.Person;
        var game = new GameShot(shot, call, inHand ? _physics!.CueBallPosition : null, PushOut);
        var sim = Session.Submit(game, source);
        if (sim is not null)
        {
            ResetShot();
            Struck?.Invoke(game);
        }
        return sim;
    }

    // The table between shots (after a ruling, a choice, a take-back, a new game), the ball the
    // next shooter strikes on it, and their ball in hand; with an option pending or the game over
    // the table waits as the shot left it.
    private void ShowTable()
    {
        ResetShot();
        if (_physics is null)
        {
            return;
        }
        _physics.CueBall = Ruleset.CueBall(Game.State);
        _physics.Load(Game.Layout());
        // The peer places their own cue ball: it is not in this player's hand.
        if (Session.BallInHand == BallInHand.None || IsOver || PendingOptions.Count > 0 || IsPeerActing)
        {
            _physics.EndBallInHand();
        }
        else
        {
            _physics.GiveBallInHand(Session.BallInHand.Region());
        }
    }

    // The shot being composed starts afresh: no call, no plan's call, no push-out declared.
    private void ResetShot()
    {
        PushOut = false;
        _hasAdoptedCall = false;
        _adoptedCall = null;
        _call.Clear();
    }
}
