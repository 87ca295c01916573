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
/// <param name="Start">The game state before the break (its rules, players and target).</param>
public sealed record GameSetup(TableSpec Table, PhysicsConfig Physics, int Seed, GameState Start)
{
    /// <summary>The game's rules.</summary>
    public GameRules Rules => Start.Rules;

    /// <summary>The ball radius of the physics (m).</summary>
    public double BallRadius => Physics.Model.BallRadius(Physics.Params);

    /// <summary>A game of <paramref name="rules"/> on a 9 ft table with the default physics.</summary>
    public static GameSetup Of(GameRules rules, int seed, PerPlayer<string>? players = null, int target = GameState.DefaultTarget) =>
        new(TableSpec.FromPreset("pool-9ft"), PhysicsConfig.Default, seed,
            new GameState(rules) { Players = players ?? GameState.DefaultPlayers, Target = target });
}

/// <summary>What a player does on one shot.</summary>
/// <param name="Shot">The cue strike.</param>
/// <param name="Call">The call (ball and pocket, or a safety), where the rules need one.</param>
/// <param name="Place">Where to put the cue ball (m) with ball in hand, or null to leave it (a pocketed cue ball goes to the head spot).</param>
/// <param name="PushOut">9-ball and 10-ball: the shot is a declared push-out.</param>
/// <param name="Choice">
/// The option the next shooter takes when the ruling offers some; null takes the first (the
/// default <see cref="Ruling.Next"/> assumes).
/// </param>
public sealed record GameShot(ShotSpec Shot, Call? Call = null, Vec3? Place = null, bool PushOut = false, RefereeOption? Choice = null);

/// <summary>One shot of a played game, as the game record keeps it.</summary>
/// <param name="Before">The game state the referee judged (with the call, the push-out and the placement).</param>
/// <param name="Input">What the player did.</param>
/// <param name="Ruling">The referee's ruling.</param>
public sealed record PlayedShot(GameState Before, GameShot Input, Ruling Ruling);

/// <summary>
/// Plays a game shot by shot: puts the balls on the table, runs each shot through the physics
/// until everything rests, asks the referee, and applies the ruling (spots, reracks, ball in hand,
/// the chosen option). Deterministic: the same setup and shots give the same rulings bit for bit.
/// </summary>
/// <remarks>
/// Each shot runs in a fresh simulation made from the balls at rest, so a shot depends only on the
/// position it starts from. Balls out of play are left out of the shot's simulation.
/// </remarks>
public sealed class GamePlayer
{
    private readonly IReferee _referee;
    private readonly List<PlayedShot> _shots = [];
    private Dictionary<int, Vec3> _balls = [];
    private int _racks;

    /// <summary>Simulated time after which a shot is judged even if balls still move (s).</summary>
    public const double MaxShotTime = 600;

    /// <summary>Racks the first rack and puts the cue ball on the head spot.</summary>
    public GamePlayer(GameSetup setup)
    {
        ArgumentNullException.ThrowIfNull(setup);
        Setup = setup;
        _referee = Referee.For(setup.Rules, setup.Table, setup.BallRadius);
        State = setup.Start;
        Rack();
    }

    /// <summary>The setup.</summary>
    public GameSetup Setup { get; }

    /// <summary>The game state before the next shot.</summary>
    public GameState State { get; private set; }

    /// <summary>True once a ruling ended the game.</summary>
    public bool IsOver => _shots.Count > 0 && _shots[^1].Ruling.GameOver;

    /// <summary>The shots played so far.</summary>
    public IReadOnlyList<PlayedShot> Shots => _shots;

    /// <summary>Where the next shooter may place the cue ball (the break places behind the head string).</summary>
    public BallInHand BallInHand => State.Shot == 0 ? BallInHand.Kitchen : State.BallInHand;

    /// <summary>The balls on the table now, at rest (the cue ball is absent while in hand after a scratch).</summary>
    public IReadOnlyDictionary<BallId, Vec3> Balls => _balls.ToDictionary(b => new BallId(b.Key), b => b.Value);

    /// <summary>Plays a whole game from its shots.</summary>
    public static GamePlayer PlayAll(GameSetup setup, IEnumerable<GameShot> shots)
    {
        ArgumentNullException.ThrowIfNull(shots);
        var player = new GamePlayer(setup);
        foreach (var shot in shots)
        {
            player.Play(shot);
        }
        return player;
    }

    /// <summary>Plays one shot and applies its ruling.</summary>
    /// <exception cref="InvalidOperationException">After the game is over, or when placing the cue ball without ball in hand.</exception>
    public PlayedShot Play(GameShot input)
    {
        ArgumentNullException.ThrowIfNull(input);
        if (IsOver)
        {
            throw new InvalidOperationException("the game is over");
        }
        double r = Setup.BallRadius;
        var before = State with { Call = input.Call, PushOut = input.PushOut, Placement = null };
        if (input.Place is { } place)
        {
            if (BallInHand == BallInHand.None)
            {
                throw new InvalidOperationException($"shot {State.Shot}: the cue ball can only be placed with ball in hand");
            }
            var p = place with { Z = r };
            _balls[0] = p;
            before = before with { Placement = p };
        }
        else if (!_balls.ContainsKey(0))
        {
            _balls[0] = Initializer.HeadSpot(Setup.Table, r);
            before = before with { Placement = _balls[0] };
        }

        var scene = new Scene("game", null, Setup.Table, Setup.Physics, null,
            [.. _balls.OrderBy(b => b.Key).Select(b => new BallSetup(new BallId(b.Key), b.Value, Vec3.Zero, Vec3.Zero))], input.Shot, Setup.Rules.ToName());
        // No wall-clock bound: a shot must end the same way on every machine.
        var sim = SimulationFactory.Create(scene);
        sim.Strike(input.Shot);
        sim.AdvanceTo(MaxShotTime);
        var ruling = _referee.Judge(before, ShotRecord.LastShot(sim, input.Shot));

        Apply(ruling, input.Choice, sim);
        var played = new PlayedShot(before, input, ruling);
        _shots.Add(played);
        return played;
    }

    private void Apply(Ruling ruling, RefereeOption? choice, Simulation sim)
    {
        var outcome = ruling.GameOver ? new OptionOutcome(ruling.Next, false, [])
            : ruling.Options.Count > 0 ? ruling.Choose(choice ?? ruling.Options[0])
            : new OptionOutcome(ruling.Next, false, ruling.Spot);
        if (!outcome.Rerack)
        {
            foreach (var ball in outcome.Spot)
            {
                sim.SpotBall(ball);
            }
        }
        _balls = [];
        var after = sim.Balls;
        for (int i = 0; i < after.Length; i++)
        {
            if (!after[i].IsPocketed)
            {
                _balls[sim.Ids[i].Value] = after[i].Position with { Z = Setup.BallRadius };
            }
        }
        State = outcome.Next;
        if (ruling.GameOver)
        {
            return;
        }
        if (outcome.Rerack)
        {
            _racks++;
            Rack();
            return;
        }
        if (ruling.Rerack.Count > 0)
        {
            RerackFourteen(ruling.Rerack);
        }
    }

    private void Rack()
    {
        double r = Setup.BallRadius;
        var game = Setup.Rules switch
        {
            GameRules.EightBall => RackGame.EightBall,
            GameRules.NineBall => RackGame.NineBall,
            GameRules.TenBall => RackGame.TenBall,
            _ => RackGame.StraightPool,
        };
        _balls = Initializer.Rack(new RackSpec(game, Setup.Seed + _racks), Setup.Table, r).ToDictionary(b => b.Id.Value, b => b.Position);
        _balls[0] = Initializer.HeadSpot(Setup.Table, r);
    }

    /// <summary>
    /// 14.1: racks the pocketed balls with the apex empty. The WPA's placement rules, simplified
    /// (ours): a fifteenth ball in the rack's way goes to the head spot (the centre spot if the cue
    /// ball is there); a cue ball in the way is taken up, and the shooter has ball in hand behind
    /// the head string.
    /// </summary>
    private void RerackFourteen(IReadOnlyList<BallId> balls)
    {
        double r = Setup.BallRadius;
        _racks++;
        var rack = Initializer.Rerack(balls, Setup.Table, r, Setup.Seed + _racks);
        bool InTheWay(Vec3 p) => rack.Any(b => (b.Position - p).Length < 2 * r) || (Initializer.FootSpot(Setup.Table, r) - p).Length < 2 * r;
        bool cueInTheWay = _balls.TryGetValue(0, out var cue) && InTheWay(cue);
        if (cueInTheWay)
        {
            _balls.Remove(0);
            State = State with { BallInHand = BallInHand.Kitchen };
        }
        foreach (var (id, _) in _balls.Where(b => b.Key != 0 && InTheWay(b.Value)).ToList())
        {
            var head = Initializer.HeadSpot(Setup.Table, r);
            bool headTaken = _balls.TryGetValue(0, out var c) && (c - head).Length < 2 * r;
            _balls[id] = headTaken ? new Vec3(0, 0, r) : head;
        }
        foreach (var (id, p) in rack)
        {
            _balls[id.Value] = p;
        }
    }
}
