using System.Numerics;
using Billiards.App.Nodes;
using Billiards.App.Rendering;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.App.Game;

/// <summary>
/// Runs the <see cref="Simulation"/> shown: steps it once per fixed step while balls roll,
/// remembers the previous step for interpolated drawing, and turns Core's state into signals
/// (struck, events, came to rest). In practice it keeps the scene's one simulation; in a match
/// (and a replay) Core's match makes each shot's simulation (<see cref="StrikeThrough"/>) and the
/// table between shots (<see cref="Load"/>), and only the referee decides a scratch. The game
/// changes physics state only through Core's API.
/// </summary>
public sealed class PhysicsNode : Node
{
    /// <summary>Seed 4.3.5: a pocketed ball stops being drawn once it has dropped below y = -20 cm (m).</summary>
    public const double DropOutOfSightZ = -0.20;

    private readonly Scene _scene;
    private Simulation _simulation;
    private BallState[] _previous;
    private int _eventsSeen;
    private Vec3 _cueAtStrike;

    /// <summary>Creates the node and its simulation from the scene.</summary>
    /// <param name="scene">The scene played.</param>
    /// <param name="createSimulation">Makes a simulation of a scene (<see cref="SimulationFactory.Create"/> in the game).</param>
    public PhysicsNode(Scene scene, Func<Scene, Simulation> createSimulation)
    {
        ArgumentNullException.ThrowIfNull(createSimulation);
        _scene = scene;
        CreateSimulation = createSimulation;
        _simulation = createSimulation(scene);
        _simulation.TrackOrientation = true; // the game draws the balls' numbers turning
        _previous = _simulation.Balls.ToArray();
        CueBall = scene.CueBall;
    }

    /// <summary>
    /// The ball the player at the table strikes: the scene's, and in a match the ruleset's for
    /// the shooter (<see cref="Core.Rules.Ruleset.CueBall"/>), which the match sets before each shot.
    /// </summary>
    public BallId CueBall { get; set; }

    /// <summary>The object balls on the table now (not pocketed, not the <see cref="CueBall"/>), in the simulation's order.</summary>
    public List<BallId> ObjectBallsOnTable()
    {
        var list = new List<BallId>();
        var sim = Simulation;
        for (int i = 0; i < sim.Ids.Count; i++)
        {
            if (sim.Ids[i] != CueBall && !sim.Balls[i].IsPocketed)
            {
                list.Add(sim.Ids[i]);
            }
        }
        return list;
    }

    /// <summary>Makes a simulation of a scene: what the node was made with (a match makes its shots with it too).</summary>
    public Func<Scene, Simulation> CreateSimulation { get; }

    /// <summary>
    /// When set (a match), a strike asks it for the shot's simulation, struck already, and runs
    /// that one: the match makes every shot from the balls at rest, as a replay does. A null
    /// answer refuses the shot (not this seat's turn, an option to choose, the game over): nothing
    /// is struck.
    /// </summary>
    public Func<ShotSpec, Simulation?>? StrikeThrough { get; set; }

    /// <summary>
    /// Shows and runs <paramref name="simulation"/> from now on (a match's table between shots);
    /// refused while balls roll. Its logged events count as seen.
    /// </summary>
    public void Load(Simulation simulation)
    {
        ArgumentNullException.ThrowIfNull(simulation);
        if (IsRolling)
        {
            throw new InvalidOperationException("cannot change the table while balls roll");
        }
        Swap(simulation);
        _eventsSeen = simulation.Events.Count;
    }

    /// <summary>
    /// Shows <paramref name="simulation"/> at once, even while balls roll (a replay jumping to
    /// another shot): the shot running is dropped without coming to rest.
    /// </summary>
    public void Interrupt(Simulation simulation)
    {
        ArgumentNullException.ThrowIfNull(simulation);
        IsRolling = false;
        EndBallInHand();
        Load(simulation);
    }

    /// <summary>
    /// Runs <paramref name="struck"/> instead of the shot just struck, before any step of it (a
    /// match takes over a scene's opening shot). The strike's events were published already.
    /// </summary>
    /// <exception cref="InvalidOperationException">When no shot is rolling, or it has stepped.</exception>
    public void ReplaceShot(Simulation struck)
    {
        ArgumentNullException.ThrowIfNull(struck);
        if (!IsRolling || _simulation.StepCount != _stepsAtStrike)
        {
            throw new InvalidOperationException("only a shot that has not moved yet can be replaced");
        }
        Swap(struck);
        _eventsSeen = struck.Events.Count;
        CaptureStrike();
    }

    private long _stepsAtStrike;

    /// <summary>The last shot's simulation and its state at the strike (its instant replay starts there), or null before the first shot or for a simulation without snapshots.</summary>
    public (Simulation Shot, SimulationSnapshot AtStrike, ShotStepping Stepping)? LastStrike { get; private set; }

    /// <summary>
    /// Takes <paramref name="shot"/>, run elsewhere (a game record's shot, run to rest and shown by
    /// its replay), as the last shot: the instant replay and the tracking lines show it.
    /// </summary>
    public void ShowStrike(Simulation shot, SimulationSnapshot atStrike, ShotStepping stepping)
    {
        ArgumentNullException.ThrowIfNull(shot);
        ArgumentNullException.ThrowIfNull(atStrike);
        LastStrike = (shot, atStrike, stepping);
    }

    /// <summary>
    /// Shows <paramref name="table"/>, a table taken back to (the session's layout before the
    /// last shot), with the cue ball in hand or not: the last shot's replay and lines are
    /// forgotten (<see cref="Undone"/>).
    /// </summary>
    public void TakeBackTo(Simulation table, bool inHand)
    {
        Load(table);
        LastShot = null;
        LastStrike = null;
        if (inHand)
        {
            GiveBallInHand(PlacementRegion.Table);
        }
        else
        {
            EndBallInHand();
        }
        Undone?.Invoke();
    }

    /// <summary>The balls on the table now (not pocketed or off it), at rest, sorted by id: a scene's balls.</summary>
    public List<BallSetup> BallsAtRest()
    {
        var balls = new List<BallSetup>();
        for (int i = 0; i < _simulation.Ids.Count; i++)
        {
            if (!_simulation.Balls[i].IsOutOfPlay)
            {
                balls.Add(new BallSetup(_simulation.Ids[i], _simulation.Balls[i].Position, Vec3.Zero, Vec3.Zero));
            }
        }
        balls.Sort((a, b) => a.Id.Value.CompareTo(b.Id.Value));
        return balls;
    }

    /// <summary>Signal: a shot was taken back (<see cref="TakeBackTo"/>).</summary>
    public event Action? Undone;

    private void CaptureStrike()
    {
        LastStrike = !_simulation.KeepsSnapshots ? null : (_simulation, _simulation.CreateSnapshot(), ShotStepping.Ticks);
    }

    private void Swap(Simulation simulation)
    {
        _simulation = simulation;
        _simulation.TrackOrientation = true;
        _previous = _simulation.Balls.ToArray();
    }

    /// <summary>Signal: the cue ball was struck with this shot.</summary>
    public event Action<ShotSpec>? Struck;

    /// <summary>Signal: the simulation logged an event (collision, cushion, pocket).</summary>
    public event Action<SimEvent>? EventOccurred;

    /// <summary>Signal: every ball is at rest after a shot; the argument is the cue ball's displacement over the shot (m).</summary>
    public event Action<Vec3>? CameToRest;

    /// <summary>The running simulation.</summary>
    public Simulation Simulation => _simulation;

    /// <summary>The scene the node was made from.</summary>
    public Scene Scene => _scene;

    /// <summary>The table.</summary>
    public TableSpec Table => _scene.Table;

    /// <summary>The scene's physics parameters (the computer player plans with them).</summary>
    public PhysicsParams Params => _scene.Physics.Params;

    /// <summary>The collision models of the scene's physics (the computer plans with them).</summary>
    public Core.Physics.Collisions.InteractionModels Models => _scene.Physics.Models;

    /// <summary>Ball radius of the scene's model (m).</summary>
    public double BallRadius => _simulation.BallRadius;

    /// <summary>True from a strike until every ball rests: all actions but viewing are locked.</summary>
    public bool IsRolling { get; private set; }

    /// <summary>The last shot played, or null before the first.</summary>
    public ShotSpec? LastShot { get; private set; }

    /// <summary>True when there is a cue ball on the table (a scratched one is placed back by hand).</summary>
    public bool HasCueBall => CueIndex is int i && !_simulation.Balls[i].IsPocketed;

    /// <summary>True from a scratch until the cue ball is struck: it is in hand and may be placed anywhere on the bed.</summary>
    public bool BallInHand { get; private set; }

    /// <summary>Where the cue ball in hand may go: the whole bed, or the kitchen after a scratch where the rules say so.</summary>
    public PlacementRegion HandRegion { get; private set; } = PlacementRegion.Table;

    /// <summary>In a match the cue ball moves by hand only when it is in hand (practice lets it move any time).</summary>
    public bool HandOnly { get; set; }

    /// <summary>
    /// Gives the cue ball in hand in a region (a referee's ruling): a pocketed cue ball, or one
    /// outside the region, comes back to the free spot nearest the head spot inside it.
    /// </summary>
    public void GiveBallInHand(PlacementRegion region)
    {
        if (IsRolling || CueIndex is not int cue)
        {
            return;
        }
        HandRegion = region;
        BallInHand = true;
        if (_simulation.Balls[cue].IsPocketed || !IsFreeSpot(CueBallPosition))
        {
            Place(ReturnSpot());
        }
    }

    /// <summary>Ends ball in hand without a shot (the referee's ruling gives none).</summary>
    public void EndBallInHand()
    {
        BallInHand = false;
        HandRegion = PlacementRegion.Table;
    }

    /// <summary>
    /// Changes the balls at rest through Core's API (spotting, reracking); refused while balls roll.
    /// Interpolation starts from the changed table, so nothing slides.
    /// </summary>
    public void Rearrange(Action<Simulation> change)
    {
        ArgumentNullException.ThrowIfNull(change);
        if (IsRolling)
        {
            throw new InvalidOperationException("cannot rearrange balls while they roll");
        }
        change(_simulation);
        _simulation.Balls.CopyTo(_previous);
    }

    /// <summary>
    /// A cue ball that dropped comes back in hand on the whole table, at the free spot nearest
    /// the head spot (<see cref="ReturnSpot"/>), and <see cref="CueBallReturned"/> says so.
    /// </summary>
    public void ReturnCueBall()
    {
        if (IsRolling || CueIndex is not int cue || !_simulation.Balls[cue].IsOutOfPlay)
        {
            return;
        }
        HandRegion = PlacementRegion.Table;
        BallInHand = true;
        Place(ReturnSpot());
        CueBallReturned?.Invoke(CueBallPosition);
    }

    /// <summary>Signal: the cue ball was pocketed and came back in hand at this position (m).</summary>
    public event Action<Vec3>? CueBallReturned;

    /// <summary>The cue ball's centre (m).</summary>
    public Vec3 CueBallPosition => CueIndex is int i ? _simulation.Balls[i].Position : Vec3.Zero;

    private int? CueIndex => _simulation.IndexOf(CueBall) is var i and >= 0 ? i : null;

    /// <summary>
    /// Places the cue ball by hand (move mode). Refused (false) while balls roll, off the bed, or
    /// overlapping another ball. The placement is handed to Core at the next strike.
    /// </summary>
    public bool TryPlaceCueBall(Vec3 position)
    {
        if (IsRolling || CueIndex is not int cue || (!BallInHand && (HandOnly || _simulation.Balls[cue].IsPocketed)))
        {
            return false;
        }
        return IsFreeSpot(position) && Place(position);
    }

    // Core places the ball (back in play, at rest); a hand-placed ball jumps, so interpolation
    // must not slide it from its old place.
    private bool Place(Vec3 position)
    {
        _simulation.PlaceBall(CueBall, position);
        _simulation.Balls.CopyTo(_previous);
        return true;
    }

    // Core's placement test: on the bed inside the cushions, over no pocket, clear of every other ball.
    private bool IsFreeSpot(Vec3 position) => _simulation.PlacementProblem(CueBall, position, BallInHand ? HandRegion : PlacementRegion.Table) is null;

    /// <summary>
    /// Where a scratched cue ball comes back: the head spot (a quarter of the length from the head
    /// rail; in snooker's D the break-off's spot), or the free point nearest to it in the region.
    /// </summary>
    public Vec3 ReturnSpot()
    {
        var others = new List<(BallId, Vec3)>();
        for (int i = 0; i < _simulation.Ids.Count; i++)
        {
            if (!_simulation.Balls[i].IsPocketed)
            {
                others.Add((_simulation.Ids[i], _simulation.Balls[i].Position));
            }
        }
        var region = BallInHand ? HandRegion : PlacementRegion.Table;
        // In snooker's D the ball comes back where the break-off starts, not to pool's head spot (outside the D).
        var near = region == PlacementRegion.D ? Initializer.CueStart(RackGame.Snooker, Table, BallRadius) : Initializer.HeadSpot(Table, BallRadius);
        return Placement.FreeSpotNear(Table, BallRadius, CueBall, near, others, region);
    }

    /// <summary>Puts every ball back where the scene had it (practice's restart); the scene's own shot is not played again.</summary>
    public void Restart()
    {
        _simulation.Reset();
        _simulation.Balls.CopyTo(_previous);
        LastStrike = null;
        _eventsSeen = 0;
        IsRolling = false;
        LastShot = null;
        EndBallInHand();
    }

    /// <summary>Strikes the cue ball; refused while balls roll, and where <see cref="StrikeThrough"/> refuses it.</summary>
    /// <exception cref="InvalidOperationException">When balls are still rolling or there is no cue ball.</exception>
    public void Strike(ShotSpec shot)
    {
        if (IsRolling)
        {
            throw new InvalidOperationException("cannot strike while balls are rolling");
        }
        if (!HasCueBall)
        {
            throw new InvalidOperationException("there is no cue ball on the table");
        }
        _cueAtStrike = CueBallPosition;
        if (StrikeThrough is { } strike)
        {
            // Asked before ball in hand ends: the match reads where the ball was placed.
            if (strike(shot) is not { } struck)
            {
                return;
            }
            EndBallInHand();
            Swap(struck);
            _eventsSeen = 0;
        }
        else
        {
            EndBallInHand();
            _simulation.Strike(shot, CueBall);
        }
        CaptureStrike();
        LastShot = shot;
        IsRolling = true;
        _stepsAtStrike = _simulation.StepCount;
        PublishEvents();
        Struck?.Invoke(shot);
    }

    /// <inheritdoc />
    protected override void Ready()
    {
        // A scene may carry an opening shot (a break, a test position): play it at once.
        if (_scene.Shot is { } shot && HasCueBall)
        {
            Strike(shot);
        }
    }

    /// <inheritdoc />
    protected override void PhysicsProcess(double dt)
    {
        if (!IsRolling)
        {
            return;
        }
        _simulation.Balls.CopyTo(_previous);
        // To the tick's time: one fixed step when the tick is the step, and the event integrator
        // stops there instead of jumping to its next event.
        _simulation.AdvanceTo(_simulation.Time + dt);
        PublishEvents();
        if (_simulation.IsAtRest)
        {
            IsRolling = false;
            // Nothing moves any more: interpolation must not pull the picture back a step.
            _simulation.Balls.CopyTo(_previous);
            // A scratched cue ball is the striking node's to rule on: a game's referee, or the
            // session without a referee of practice and of a scene without a game (ReturnCueBall).
            var displacement = HasCueBall ? CueBallPosition - _cueAtStrike : Vec3.Zero;
            CameToRest?.Invoke(displacement);
        }
    }

    /// <inheritdoc />
    protected override void Draw(FrameBuilder frame)
    {
        frame.Frame.BallRadius = (float)BallRadius;
        frame.Frame.BallSet = _simulation.BallSet;
        var balls = _simulation.Balls;
        float alpha = (float)frame.Alpha;
        for (int i = 0; i < balls.Length; i++)
        {
            frame.Frame.Balls.Add(Visual(_simulation.Ids[i], _previous[i], balls[i], alpha, BallRadius));
        }
    }

    /// <summary>A shot's replay drawn in the table's place (a node drawn after this one calls it): its balls at the replay's time, and no cue.</summary>
    public static void DrawInstead(FrameBuilder frame, ShotReplay replay)
    {
        ArgumentNullException.ThrowIfNull(frame);
        ArgumentNullException.ThrowIfNull(replay);
        var balls = frame.Frame.Balls;
        balls.Clear();
        var previous = replay.Previous;
        var current = replay.Current;
        for (int i = 0; i < current.Length; i++)
        {
            balls.Add(Visual(replay.Ids[i], previous[i], current[i], (float)replay.Alpha, replay.BallRadius));
        }
        frame.Frame.Cue = default;
    }

    /// <summary>
    /// How a ball is drawn between two states of it: its position and turn interpolated by
    /// <paramref name="alpha"/>, shown unless it is pocketed and has dropped out of sight.
    /// </summary>
    public static BallVisual Visual(BallId id, in BallState previous, in BallState current, float alpha, double radius)
    {
        var position = Vector3.Lerp(previous.Position.ToVector3(), current.Position.ToVector3(), alpha);
        // A ball at rest is drawn exactly where it is (interpolating between equal states still
        // rounds differently with every alpha), so a still table stays bit for bit the same
        // and the renderer can keep it.
        var orientation = previous.Orientation == current.Orientation
            ? Valid(current.Orientation)
            : Quaternion.Slerp(Valid(previous.Orientation), Valid(current.Orientation), alpha);
        if (previous.Position == current.Position)
        {
            position = current.Position.ToVector3();
        }
        return new BallVisual(id, position, orientation, IsVisible(current, radius));
    }

    private static bool IsVisible(in BallState ball, double radius) =>
        // A pocketed ball is drawn only while it drops (seed 4.3.5); one resting at the pocket is not.
        !ball.IsPocketed || (ball.Position.Z < radius - 1e-6 && ball.Position.Z > DropOutOfSightZ);

    // A simulation that does not track orientation leaves default (all-zero) quaternions.
    private static Quaternion Valid(Quaternion q) => q.LengthSquared() > 1e-12f ? q : Quaternion.Identity;

    private void PublishEvents()
    {
        var log = _simulation.Events;
        if (log.Count < _eventsSeen)
        {
            _eventsSeen = 0; // the simulation cleared its log for a new shot
        }
        for (; _eventsSeen < log.Count; _eventsSeen++)
        {
            EventOccurred?.Invoke(log[_eventsSeen]);
        }
    }
}
