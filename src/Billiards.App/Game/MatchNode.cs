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
    // Who strikes the shot passing through now (the keys and the mouse are a person's), and a shot given whole.
    private SeatKind _source = SeatKind.Person;
    private GameShot? _given;

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

    /// <summary>True while the person at this table only watches: the computer's or the peer's move, or a game held by the network.</summary>
    public bool IsWatching => Session.IsComputerActing || Session.IsRemoteActing || Session.IsHeld;

    /// <summary>The keyboard power (m/s).</summary>
    public double Power { get; private set; } = DefaultPower;

    /// <summary>True when the shooter declared a push-out for the shot being composed.</summary>
    public bool PushOut { get; private set; }

    /// <summary>The match's seed for the computer player (default 1).</summary>
    public ulong MatchSeed { get; init; } = 1;

    /// <summary>The seed of the planner's search and of the computer's error for the shot to come (<see cref="Session.ShotSeed"/>).</summary>
    public ulong ShotSeed(long stream) => Session.ShotSeed(MatchSeed, stream);

    /// <summary>True when the shooter may strike now: balls at rest, a cue ball, and the session's yes (no option pending, the game on).</summary>
    public bool CanShoot => _physics is { IsRolling: false, HasCueBall: true } && !Session.IsOver && !Session.IsHeld && Session.PendingOptions.Count == 0;

    /// <summary>Takes the last shot back (<see cref="Session.TakeBack"/>, which the network never allows); false while balls roll or when the session refuses.</summary>
    public bool TakeBack() => _physics is { IsRolling: false } && Session.TakeBack();

    /// <summary>The aim preview of the moment, or null without a cue ball or while balls roll.</summary>
    public AimPreview? Aim => _physics is { IsRolling: false, HasCueBall: true } physics && _cue is not null && _call.Geometry is { } geometry
        ? AimPreview.Compute(physics.Simulation.Balls, physics.Simulation.Ids, physics.Simulation.IndexOf(physics.CueBall), _cue.AimDirection, physics.BallRadius, geometry.Pockets, physics.Table.Pockets)
        : null;

    /// <summary>The cue's aim now (deg, from +x counter-clockwise).</summary>
    public double AimDegrees => _cue is null ? 0 : ViewMath.AimDegrees(_cue.AimDirection);

    /// <summary>True when the rules call this shot.</summary>
    public bool NeedsCall => Session.Ruleset.NeedsCall(Session.State);

    /// <summary>True when the shooter nominates a ball without a pocket.</summary>
    public bool NeedsNomination => Session.Ruleset.Nominates(Session.State);

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
            PlaceCueBall(place);
        }
        _call.Take(decision.Call);
        _adoptedCall = exactCall ? decision.Call : null;
        _hasAdoptedCall = exactCall;
        PushOut |= decision.PushOut && Session.Ruleset.MayPushOut(Session.State);
        if (!exactCall)
        {
            // A hint sets the person's power; the computer strikes its own shot and leaves the person's power alone.
            Power = Math.Clamp(decision.Shot.Speed, MinPower, MaxPower);
            _cue?.Take(decision.Shot);
        }
        AimAt(decision.Shot.AimDeg);
    }

    /// <summary>Places the cue ball in hand at <paramref name="place"/> when it may lie there, the view following it.</summary>
    public void PlaceCueBall(Billiards.Core.Mathematics.Vec3 place)
    {
        var old = _physics!.CueBallPosition;
        if (_physics.TryPlaceCueBall(place) && _camera is not null)
        {
            _camera.Camera.Translate(_physics.CueBallPosition - old);
        }
    }

    /// <summary>Strikes a shot the computer plays (its plan with its own error), with the call it adopted; the session refuses it when it is not the computer's turn.</summary>
    public void StrikeAsComputer(ShotSpec shot)
    {
        if (CanShoot)
        {
            StrikeFrom(SeatKind.Computer, _cue?.Playable(shot) ?? shot, null);
        }
    }

    /// <summary>
    /// Carries out the incoming player's choice at this table (<see cref="Session.Choose"/>);
    /// ignored while the peer chooses or the network holds the game.
    /// </summary>
    /// <exception cref="ArgumentException">When the option is not offered now.</exception>
    public void Choose(RefereeOption option)
    {
        if (!Session.IsRemoteActing && !Session.IsHeld)
        {
            Session.Choose(option);
        }
    }

    /// <summary>
    /// Strikes a whole shot as it was made elsewhere (its placement, call and push-out: a network
    /// peer's) from <paramref name="source"/>; false when the session refuses it (not that seat's turn).
    /// </summary>
    public bool StrikeGiven(GameShot shot, SeatKind source)
    {
        ArgumentNullException.ThrowIfNull(shot);
        return _physics is { IsRolling: false, HasCueBall: true } && StrikeFrom(source, shot.Shot, shot);
    }

    private bool StrikeFrom(SeatKind source, ShotSpec shot, GameShot? given)
    {
        (_source, _given) = (source, given);
        try
        {
            _physics!.Strike(shot);
        }
        finally
        {
            (_source, _given) = (SeatKind.Person, null);
        }
        return _physics.IsRolling;
    }

    /// <summary>A new game after the last one ended (<see cref="Session.Rematch"/>); not over the network.</summary>
    public bool Rematch() => !IsNetworked && Session.Rematch();

    /// <summary>The game starts again (the pause menu), while no ball rolls (<see cref="Session.Restart"/>); not over the network.</summary>
    public bool Restart() => _physics is { IsRolling: false } && !IsNetworked && Session.Restart();

    /// <summary>True for a game with a remote seat: no take-back, restart or rematch (the other side would not follow).</summary>
    public bool IsNetworked => Session.Seats.Any(s => s.Kind == SeatKind.Remote);

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
            case >= Key.D1 and <= Key.D5 when (int)(key.Key - Key.D1) < Session.PendingOptions.Count:
                Choose(Session.PendingOptions[key.Key - Key.D1]);
                return true;
            case Key.Enter when Session.IsOver:
                Rematch();
                return true;
            case Key.Space when CanShoot && _cue is not null:
                bool power = Session.Ruleset.IsPowerBreak(Session.State);
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
            case Key.O when CanShoot && Session.Ruleset.MayPushOut(Session.State):
                PushOut = !PushOut;
                Session.Say(PushOut ? $"{Session.State.ShooterName} declares a push-out." : "Push-out withdrawn.");
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

    // Every strike in the window (Space, the mouse, the computer, a peer) arrives here: the session says
    // whether it may be struck now and makes its simulation from the balls at rest.
    private Core.Physics.Simulation? OnStrike(ShotSpec shot)
    {
        if (_given is null && Session.Held is not null)
        {
            return null;
        }
        bool inHand = Session.BallInHand != BallInHand.None;
        var call = _hasAdoptedCall ? _adoptedCall : NeedsCall ? _call.CurrentCall : NeedsNomination ? _call.CurrentNomination : null;
        // A shot given whole (a peer's) as it came: the session checks the seat, the placement and the call.
        var game = _given is { } given ? given with { Shot = shot } : new GameShot(shot, call, inHand ? _physics!.CueBallPosition : null, PushOut);
        var sim = Session.Submit(game, _source);
        if (sim is not null)
        {
            ResetShot();
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
        _physics.CueBall = Session.Ruleset.CueBall(Session.Game.State);
        _physics.Load(Session.Game.Layout());
        // The peer places their own cue ball: it is not in this player's hand.
        if (Session.BallInHand == BallInHand.None || Session.IsOver || Session.PendingOptions.Count > 0 || Session.IsRemoteActing)
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
