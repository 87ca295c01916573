using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Rules;

/// <summary>How a game is set up: rules, table, physics, the rack's seed and the state at the start.</summary>
/// <param name="Table">The table.</param>
/// <param name="Physics">The physics every shot runs with.</param>
/// <param name="Seed">Seed of the first rack's jitter; rack k (a rerack) uses Seed + k.</param>
/// <param name="Start">The game state before the first shot (its rules, players and target).</param>
public sealed record GameSetup(TableSpec Table, PhysicsConfig Physics, int Seed, GameState Start)
{
    /// <summary>The game's rules.</summary>
    public GameRules Rules => Start.Rules;

    /// <summary>The game's ruleset.</summary>
    public Ruleset Ruleset => Ruleset.For(Start.Rules);

    /// <summary>The ball radius of the physics (m).</summary>
    public double BallRadius => Physics.Model.BallRadius(Physics.Params);

    /// <summary>
    /// The balls of the first shot when the game does not start from its rack (a scene's
    /// position), cue ball included, in the ball set's order; null for the rack with the cue ball
    /// on the head spot.
    /// </summary>
    public BallLayout? Position { get; init; }

    /// <summary>A game of <paramref name="rules"/> on its ruleset's table (pool's 9 ft, snooker's 12 ft) with the default physics for its balls.</summary>
    public static GameSetup Of(GameRules rules, int seed, PerPlayer<string>? players = null, int? target = null)
    {
        var ruleset = Ruleset.For(rules);
        return new(TableSpec.FromPreset(ruleset.TablePreset), PhysicsConfig.Default with { Params = ruleset.BallSet.DefaultParams }, seed,
            new GameState(rules) { Players = players ?? GameState.DefaultPlayers, Target = target ?? ruleset.DefaultTarget });
    }

    /// <summary>The rack of <paramref name="rack"/> (0 the first) with the cue ball where the rack puts it (the head spot; snooker's D).</summary>
    public BallLayout Racked(int rack)
    {
        var balls = Ruleset.Rack(Start, Table, BallRadius, Seed + rack);
        var cue = Ruleset.CueBall(Start);
        return new(balls.Any(b => b.Id == cue) ? balls : [(cue, Ruleset.CueStart(Table, BallRadius)), .. balls]);
    }
}

/// <summary>What a player does on one shot.</summary>
/// <param name="Shot">The cue strike.</param>
/// <param name="Call">The call (ball and pocket, or a safety), where the rules need one.</param>
/// <param name="Place">Where to put the cue ball (m) with ball in hand, or null to leave it (a pocketed cue ball goes to the head spot).</param>
/// <param name="PushOut">9-ball and 10-ball: the shot is a declared push-out.</param>
/// <param name="Choice">
/// The option the next shooter takes when the ruling offers some; null leaves the choice to
/// <see cref="Match.Choose"/> (<see cref="Match.Play"/> then takes the first).
/// </param>
public sealed record GameShot(ShotSpec Shot, Call? Call = null, Vec3? Place = null, bool PushOut = false, RefereeOption? Choice = null);

/// <summary>One shot of a match, as the game record keeps it.</summary>
/// <param name="Before">The game state the referee judged (with the call, the push-out and the placement).</param>
/// <param name="Input">What the player did (with the option the next shooter took).</param>
/// <param name="Ruling">The referee's ruling.</param>
/// <param name="After">The balls at rest after the shot, before the ruling's spots and reracks (m, z = R), in the ball set's order.</param>
public sealed record MatchShot(GameState Before, GameShot Input, Ruling Ruling, BallLayout After);

/// <summary>
/// The one state machine of a game, driven alike by the window, self-play and replays: it keeps
/// the balls at rest and the state between shots; it makes each shot's simulation
/// (<see cref="Strike"/>), judges the finished shot with the ruleset's referee (<see cref="Judge"/>)
/// and applies the ruling: spots, reracks, ball in hand, and the incoming player's option
/// (<see cref="Choose"/>). Only the referee decides a scratch.
/// </summary>
/// <remarks>
/// Each shot runs in a fresh simulation made from the balls at rest, so a shot depends only on the
/// position it starts from, and a recorded game replays bit for bit however its shots were
/// stepped (a window steps one fixed step per tick, a replay runs to rest at once: the same steps).
/// Balls out of play are left out of the shot's simulation.
/// </remarks>
/// <example>
/// A 9-ball game from its seeded rack: the break struck, simulated to rest and judged in one call
/// (<see cref="Strike"/>, <see cref="RunToRest"/> and <see cref="Judge"/> are its three steps):
/// <code language="csharp">
/// var match = new Match(GameSetup.Of(GameRules.NineBall, seed: 1));
/// MatchShot shot = match.Play(new GameShot(new ShotSpec(Speed: 8, AimDeg: 0)));
/// Console.WriteLine(shot.Ruling.Message);          // a sentence: who is at the table, or the foul
/// if (match.PendingOptions.Count &gt; 0)
/// {
///     match.Choose(match.PendingOptions[0]);        // the incoming player's choice, when offered
/// }
/// </code>
/// </example>
public sealed class Match
{
    private readonly Func<Scene, Simulation> _createSimulation;
    private readonly List<MatchShot> _shots = [];
    private BallLayout _balls;
    private BallLayout _beforeShot = BallLayout.Empty;
    private int _racks;
    private (GameState Before, GameShot Input)? _struck;
    private Simulation? _judged;

    /// <summary>Simulated time after which a shot is judged even if balls still move (s).</summary>
    public const double MaxShotTime = 600;

    /// <summary>Sets up the first position (the setup's, else its rack with the cue ball on the head spot).</summary>
    /// <param name="setup">The game.</param>
    /// <param name="createSimulation">Makes a shot's simulation; <see cref="SimulationFactory.Create"/> by default.</param>
    public Match(GameSetup setup, Func<Scene, Simulation>? createSimulation = null)
    {
        ArgumentNullException.ThrowIfNull(setup);
        Setup = setup;
        Ruleset = setup.Ruleset;
        Referee = Ruleset.Referee(setup.Table, setup.BallRadius);
        _createSimulation = createSimulation ?? SimulationFactory.Create;
        State = setup.Start;
        _balls = setup.Position ?? setup.Racked(0);
    }

    /// <summary>The setup.</summary>
    public GameSetup Setup { get; }

    /// <summary>The game's ruleset.</summary>
    public Ruleset Ruleset { get; }

    /// <summary>The game's referee.</summary>
    public IReferee Referee { get; }

    /// <summary>The game state before the next shot (while an option is pending: the state its first option gives).</summary>
    public GameState State { get; private set; }

    /// <summary>True once a ruling ended the game.</summary>
    public bool IsOver => _shots.Count > 0 && _shots[^1].Ruling.GameOver;

    /// <summary>The shots played so far.</summary>
    public IReadOnlyList<MatchShot> Shots => _shots;

    /// <summary>The last ruling, or null before the first shot is judged.</summary>
    public Ruling? LastRuling => _shots.Count > 0 ? _shots[^1].Ruling : null;

    /// <summary>The options the incoming player must choose from before the next shot (empty when none).</summary>
    public IReadOnlyList<RefereeOption> PendingOptions => _judged is null ? [] : LastRuling!.Options;

    /// <summary>True from <see cref="Strike"/> until <see cref="Judge"/>.</summary>
    public bool IsShotRunning => _struck is not null;

    /// <summary>The state the referee will judge the running shot by (with its call, push-out and placement), or null.</summary>
    public GameState? RunningShotState => _struck?.Before;

    /// <summary>The running shot: the state it is judged by and what the player did; null between shots.</summary>
    public (GameState Before, GameShot Input)? RunningShot => _struck;

    /// <summary>Where the next shooter may place the cue ball (the break places behind the head string, in snooker in the D).</summary>
    public BallInHand BallInHand => State.Shot == 0 ? Ruleset.BreakBallInHand : State.BallInHand;

    /// <summary>The balls on the table now, at rest (the cue ball is absent while in hand after a scratch).</summary>
    public BallLayout Balls => _balls;

    /// <summary>
    /// The table as it stands between shots, as a simulation at rest, for a window to show and to
    /// place the cue ball in: the balls on the table, and a cue ball in hand where it would go back
    /// (the free spot nearest the head spot in its region; the head spot itself without ball in hand).
    /// </summary>
    public Simulation Layout()
    {
        var balls = _balls;
        var cue = Ruleset.CueBall(State);
        if (!balls.Contains(cue))
        {
            var region = BallInHand.Region();
            var head = Ruleset.CueStart(Setup.Table, Setup.BallRadius);
            balls = balls.With(cue, BallInHand == BallInHand.None ? head
                : Placement.FreeSpotNear(Setup.Table, Setup.BallRadius, cue, head, balls, region));
        }
        var sim = _createSimulation(SceneOf(balls, null));
        sim.RefereeRules = true;
        return sim;
    }

    /// <summary>Plays one shot headless through the one shot loop (<see cref="Session.Play"/>: strike, run to rest, judge) and applies its ruling; an offered option defaults to the first.</summary>
    /// <exception cref="InvalidOperationException">After the game is over, with an option pending, or when placing the cue ball without ball in hand.</exception>
    public MatchShot Play(GameShot input) => Session.Over(this).Play(input, SeatKind.Script);

    /// <summary>Plays a whole game from its shots.</summary>
    public static Match PlayAll(GameSetup setup, IEnumerable<GameShot> shots)
    {
        ArgumentNullException.ThrowIfNull(shots);
        var match = new Match(setup);
        foreach (var shot in shots)
        {
            match.Play(shot);
        }
        return match;
    }

    /// <summary>
    /// Starts a shot: places the cue ball (with ball in hand, else a missing one on the head spot),
    /// makes the shot's simulation from the balls at rest and strikes. The caller runs it to rest
    /// (<see cref="RunToRest"/>, or a window's fixed steps) and hands it to <see cref="Judge"/>.
    /// </summary>
    /// <exception cref="InvalidOperationException">After the game is over, with an option pending or a shot running, or when placing the cue ball without ball in hand.</exception>
    public Simulation Strike(GameShot input)
    {
        ArgumentNullException.ThrowIfNull(input);
        if (IsOver)
        {
            throw new InvalidOperationException("the game is over");
        }
        if (_struck is not null || _judged is not null)
        {
            throw new InvalidOperationException(_struck is not null ? "a shot is still running" : "an option must be chosen before the next shot");
        }
        double r = Setup.BallRadius;
        var cue = Ruleset.CueBall(State);
        var before = State with { Call = input.Call, PushOut = input.PushOut, Placement = null };
        if (input.Place is { } place)
        {
            if (BallInHand == BallInHand.None)
            {
                throw new InvalidOperationException($"shot {State.Shot}: the cue ball can only be placed with ball in hand");
            }
            var p = place with { Z = r };
            _balls = _balls.With(cue, p);
            before = before with { Placement = p };
        }
        else if (!_balls.Contains(cue))
        {
            var head = Ruleset.CueStart(Setup.Table, r);
            _balls = _balls.With(cue, head);
            before = before with { Placement = head };
        }
        _beforeShot = _balls;
        // No wall-clock bound: a shot must end the same way on every machine.
        var sim = _createSimulation(SceneOf(_balls, input.Shot));
        sim.RefereeRules = true;
        sim.Strike(input.Shot, cue);
        _struck = (before, input);
        return sim;
    }

    /// <summary>Runs a struck shot until every ball rests (or <see cref="MaxShotTime"/>).</summary>
    public static void RunToRest(Simulation simulation)
    {
        ArgumentNullException.ThrowIfNull(simulation);
        simulation.AdvanceTo(MaxShotTime);
    }

    /// <summary>
    /// Judges the shot <see cref="Strike"/> started, now at rest in <paramref name="simulation"/>,
    /// and applies the ruling. When the ruling offers options and the shot's input chose none,
    /// the table waits as the shot left it until <see cref="Choose"/>.
    /// </summary>
    /// <exception cref="InvalidOperationException">When no shot was struck.</exception>
    public MatchShot Judge(Simulation simulation)
    {
        ArgumentNullException.ThrowIfNull(simulation);
        if (_struck is not { } struck)
        {
            throw new InvalidOperationException("no shot was struck");
        }
        _struck = null;
        var record = ShotRecord.LastShot(simulation, struck.Input.Shot);
        var ruling = Referee.Judge(struck.Before, record);
        _balls = AtRest(simulation);
        var played = new MatchShot(struck.Before, struck.Input, ruling, Ordered(_balls));
        _shots.Add(played);
        if (ruling.GameOver)
        {
            Apply(ruling, new OptionOutcome(ruling.Next, false, []), simulation);
        }
        else if (ruling.Options.Count == 0)
        {
            Apply(ruling, new OptionOutcome(ruling.Next, false, ruling.Spot), simulation);
        }
        else if (struck.Input.Choice is { } choice)
        {
            Apply(ruling, Ruleset.Choose(ruling, choice), simulation);
        }
        else
        {
            _judged = simulation;
            State = ruling.Next;
        }
        return played;
    }

    /// <summary>Carries out the incoming player's choice among the last ruling's options; the record keeps it.</summary>
    /// <exception cref="ArgumentException">When the option is not offered now.</exception>
    public void Choose(RefereeOption option)
    {
        if (_judged is not { } sim || !PendingOptions.Contains(option))
        {
            throw new ArgumentException($"\"{option.ToName()}\" is not offered now", nameof(option));
        }
        _judged = null;
        var last = _shots[^1];
        _shots[^1] = last with { Input = last.Input with { Choice = option } };
        Apply(last.Ruling, Ruleset.Choose(last.Ruling, option), sim);
    }

    /// <summary>
    /// The match's whole state between shots (the balls at rest, the game state, the shots played,
    /// the reracks so far), for a take-back and for retrying a shot: <see cref="Restore"/> puts the
    /// match back there bit for bit, and the game then goes on as it would have from there.
    /// </summary>
    /// <exception cref="InvalidOperationException">While a shot runs or an option is pending (no shot can start then either).</exception>
    public MatchSnapshot Snapshot()
    {
        if (_struck is not null || _judged is not null)
        {
            throw new InvalidOperationException(_struck is not null ? "a shot is still running" : "an option must be chosen first");
        }
        return new MatchSnapshot(Setup, State, Ordered(_balls), [.. _shots], _racks);
    }

    /// <summary>
    /// Puts the match back in the state of <paramref name="snapshot"/>: the balls bit for bit, the
    /// game state, the shots played (later ones are dropped) and the reracks. A running shot or a
    /// pending option is abandoned.
    /// </summary>
    /// <exception cref="ArgumentException">The snapshot is of another game (another setup).</exception>
    public void Restore(MatchSnapshot snapshot)
    {
        ArgumentNullException.ThrowIfNull(snapshot);
        if (!Equals(snapshot.Setup, Setup))
        {
            throw new ArgumentException("the snapshot was taken from another game", nameof(snapshot));
        }
        _struck = null;
        _judged = null;
        State = snapshot.State;
        _balls = snapshot.Balls;
        _shots.Clear();
        _shots.AddRange(snapshot.Shots);
        _racks = snapshot.Racks;
    }

    private void Apply(Ruling ruling, OptionOutcome outcome, Simulation sim)
    {
        if (outcome.Replace)
        {
            // Snooker's replace: every ball back where it stood before the shot.
            _balls = _beforeShot;
        }
        else if (!outcome.Rerack && outcome.Spot.Count > 0)
        {
            Ruleset.SpotBalls(sim, outcome.Spot);
            _balls = AtRest(sim);
        }
        State = outcome.Next;
        if (ruling.GameOver)
        {
            return;
        }
        if (outcome.Rerack)
        {
            _racks++;
            _balls = Setup.Racked(_racks);
            return;
        }
        if (ruling.Rerack.Count > 0)
        {
            _racks++;
            var (balls, hand) = Ruleset.RerackDuringPlay(_balls, ruling.Rerack, Setup.Table, Setup.BallRadius, Setup.Seed + _racks);
            _balls = balls;
            if (hand is not null)
            {
                State = State with { BallInHand = hand.Value };
            }
        }
    }

    // The balls in play at rest; a ball the shot pocketed is off the table whatever the model did after.
    private BallLayout AtRest(Simulation sim) => sim.InPlay(Setup.BallRadius);

    private BallLayout Ordered(BallLayout balls) => balls.OrderedBy(Ruleset.BallSet.Ids);

    private Scene SceneOf(BallLayout balls, ShotSpec? shot) =>
        Scene.Of(Ordered(balls), Setup.Table, Setup.Physics, Ruleset.BallSet, shot, Ruleset.Name);
}

/// <summary>
/// A match's state between two shots (<see cref="Match.Snapshot"/>), immutable: restoring it
/// (<see cref="Match.Restore"/>) any number of times gives the same position and game state.
/// </summary>
public sealed class MatchSnapshot
{
    internal MatchSnapshot(GameSetup setup, GameState state, BallLayout balls, IReadOnlyList<MatchShot> shots, int racks)
    {
        Setup = setup;
        State = state;
        Balls = balls;
        Shots = shots;
        Racks = racks;
    }

    /// <summary>The game the snapshot belongs to.</summary>
    public GameSetup Setup { get; }

    /// <summary>The game state before the next shot.</summary>
    public GameState State { get; }

    /// <summary>The balls at rest on the table (m, z = R), in the ball set's order; a cue ball in hand is absent.</summary>
    public BallLayout Balls { get; }

    /// <summary>The shots played before the snapshot.</summary>
    public IReadOnlyList<MatchShot> Shots { get; }

    /// <summary>Reracks so far (rack k racks with the setup's seed + k).</summary>
    internal int Racks { get; }
}
