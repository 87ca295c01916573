using System.Text.Json;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Rules;

/// <summary>What the HUD shows as a player's target: a few words and the balls to draw as icons.</summary>
/// <param name="Text">The words, e.g. "solids: 1 3 6" or "on the 4".</param>
/// <param name="Balls">The balls the player still needs, in number order.</param>
public sealed record HudTarget(string Text, IReadOnlyList<BallId> Balls);

/// <summary>One visit to the table (<see cref="Ruleset.Visits"/>).</summary>
/// <param name="Player">The player at the table, 0 or 1.</param>
/// <param name="Shots">The shots of the visit.</param>
/// <param name="Break">Its break (<see cref="Ruleset.BreakValue"/> summed over its shots).</param>
/// <param name="Open">True when its last shot kept the player at the table: the visit goes on.</param>
public readonly record struct Visit(int Player, int Shots, int Break, bool Open);

/// <summary>
/// Everything one game knows, as one object (conventions.md: "a game is a ruleset object"): its
/// balls and rack, its referee, the next shot's constraints (legal targets, whether the shot is
/// called, push-out), what each option of the incoming player leads to, and what the HUD shows.
/// The match, the computer player, the scene reader and the HUD ask the ruleset instead of asking
/// which game is played; <see cref="For"/> is the one place that maps a game to its ruleset.
/// Its members by role: <see cref="IShotConstraints"/>, <see cref="IRefereeRules"/>,
/// <see cref="IGamePresentation"/> and <see cref="IPlannerPolicy"/>, and its own part of the state,
/// <see cref="IGameStateRules"/>; a layer takes the role it needs.
/// </summary>
public abstract class Ruleset : IShotConstraints, IRefereeRules, IGamePresentation, IPlannerPolicy, IGameStateRules
{
    private static readonly Lock RegistryLock = new();
    private static Ruleset[] _registered = [new EightBallRuleset(), new NineBallRuleset(), new TenBallRuleset(), new StraightPoolRuleset(), new SnookerRuleset(), new ThreeCushionRuleset()];

    /// <summary>Every registered ruleset, in the order of registration (the shipped six first).</summary>
    public static IReadOnlyList<Ruleset> All => Volatile.Read(ref _registered);

    /// <summary>
    /// Registers a game (its ruleset by its name): from then on scenes, records, <c>selfplay
    /// --rules</c> and the window know it. Registering the same ruleset type again does nothing.
    /// </summary>
    /// <exception cref="ArgumentException">When another ruleset already has the name.</exception>
    public static void Register(Ruleset ruleset)
    {
        ArgumentNullException.ThrowIfNull(ruleset);
        lock (RegistryLock)
        {
            if (Find(ruleset.Name) is { } known)
            {
                if (known.GetType() != ruleset.GetType())
                {
                    throw new ArgumentException($"a game named \"{ruleset.Name}\" is registered already", nameof(ruleset));
                }
                return;
            }
            Volatile.Write(ref _registered, [.. _registered, ruleset]);
        }
    }

    /// <summary>The registered ruleset named <paramref name="name"/>, or null.</summary>
    public static Ruleset? Find(string name)
    {
        // Asked on every judged shot of a search: an array walk, no enumerator.
        var registered = Volatile.Read(ref _registered);
        for (int i = 0; i < registered.Length; i++)
        {
            if (registered[i].Name == name)
            {
                return registered[i];
            }
        }
        return null;
    }

    /// <summary>The ruleset of <paramref name="game"/>.</summary>
    /// <example>
    /// Ask the game, not which game it is:
    /// <code language="csharp">
    /// Ruleset nineBall = Ruleset.For(GameRules.NineBall);
    /// bool called = nineBall.CallsShots;      // false: 9-ball calls no shot
    /// bool threeFouls = nineBall.HasThreeFouls; // true: three fouls in a row lose
    /// </code>
    /// </example>
    /// <exception cref="ArgumentOutOfRangeException">For a game no ruleset is registered for.</exception>
    public static Ruleset For(GameRules game) => (game.Name is null ? null : Find(game.Name))
        ?? (game == PracticeRuleset.Practice ? PracticeRuleset.Instance : null)
        ?? throw new ArgumentOutOfRangeException(nameof(game), game, "no such game");

    /// <summary>The game.</summary>
    public abstract GameRules Game { get; }

    /// <summary>The game's name in files, e.g. "eight-ball".</summary>
    public string Name => Game.Name;

    /// <summary>The game's short name for people, e.g. "8-ball" (the scoreboard's).</summary>
    public abstract string ShortName { get; }

    /// <summary>The game's name for people in a title, e.g. "14.1 straight pool" (the window's).</summary>
    public virtual string Title => ShortName;

    /// <summary>The ball set the game is played with.</summary>
    public virtual BallSet BallSet => BallSet.Pool;

    /// <summary>The cue ball the shooter of <paramref name="state"/> strikes (pool: the one cue ball; carom's players each have their own).</summary>
    public virtual BallId CueBall(GameState state) => BallSet.CueBalls[0];

    /// <summary>The balls of a game, cue ball first (a subset of <see cref="BallSet"/>).</summary>
    public abstract IReadOnlyList<BallId> Balls { get; }

    /// <summary>
    /// The shape of the game's rack, where it is one of the shapes the scene format knows; a game
    /// with a rack of its own overrides <see cref="Rack(TableSpec, double, int)"/> and <see cref="CueStart"/> instead.
    /// </summary>
    protected virtual RackGame RackShape => throw new NotSupportedException($"{Name} racks its own balls (Ruleset.Rack)");

    /// <summary>The object balls racked for a break with the rack's jitter from <paramref name="seed"/> (m, z = R).</summary>
    public virtual IReadOnlyList<(BallId Id, Vec3 Position)> Rack(TableSpec table, double ballRadius, int seed) =>
        Initializer.Rack(new RackSpec(RackShape, seed), table, ballRadius);

    /// <summary>
    /// The balls racked for the break of a game that starts at <paramref name="start"/>: by default
    /// <see cref="Rack(TableSpec, double, int)"/>; three-cushion places the breaker's ball by the shooter.
    /// </summary>
    public virtual IReadOnlyList<(BallId Id, Vec3 Position)> Rack(GameState start, TableSpec table, double ballRadius, int seed) => Rack(table, ballRadius, seed);

    /// <summary>The points that win a game of the ruleset by default (14.1's 100; three-cushion's 40).</summary>
    public virtual int DefaultTarget => GameState.DefaultTarget;

    /// <summary>
    /// True when the game keeps innings, an average and runs on its score sheet (three-cushion):
    /// its game blocks carry cue_balls, innings, equalizing, breaker and run, its rulings point,
    /// cushions, innings, average and run.
    /// </summary>
    public virtual bool HasInnings => false;

    /// <summary>The table the game is played on by default (a preset of <see cref="TableSpec.FromPreset"/>).</summary>
    public virtual string TablePreset => "pool-9ft";

    /// <summary>Where the break places the cue ball from hand: behind the head string in pool, in the D in snooker.</summary>
    public virtual BallInHand BreakBallInHand => BallInHand.Kitchen;

    /// <summary>Where a rack's cue ball starts (m, z = R): the head spot in pool, in the D in snooker.</summary>
    public virtual Vec3 CueStart(TableSpec table, double ballRadius) => Initializer.CueStart(RackShape, table, ballRadius);

    /// <summary>
    /// Puts the ruling's <paramref name="balls"/> back on the table at rest in
    /// <paramref name="simulation"/>: pool spots them on the foot spot (or behind it on the long
    /// axis); snooker puts each colour on its own spot or the next free one.
    /// </summary>
    public virtual void SpotBalls(Physics.Simulation simulation, IReadOnlyList<BallId> balls)
    {
        ArgumentNullException.ThrowIfNull(simulation);
        ArgumentNullException.ThrowIfNull(balls);
        foreach (var ball in balls)
        {
            SpotOnFootSpot(simulation, ball);
        }
    }

    /// <summary>
    /// Pool's spotting (rules.md): ball <paramref name="id"/> goes on the foot spot (x = +L/4,
    /// y = 0), or at the nearest point behind it on the long axis (towards the foot rail) where it
    /// touches no other ball; when no such point is left before the foot cushion, at the nearest
    /// one in front of it. The ball's own current place does not count against it. Only between shots.
    /// </summary>
    /// <returns>Where the ball was put (m).</returns>
    /// <exception cref="Physics.PlacementException">When the ball is not in the simulation, or the whole long axis is taken.</exception>
    /// <exception cref="InvalidOperationException">While balls move.</exception>
    public static Vec3 SpotOnFootSpot(Physics.Simulation simulation, BallId id)
    {
        ArgumentNullException.ThrowIfNull(simulation);
        int index = simulation.IndexOf(id);
        if (index < 0)
        {
            throw new Physics.PlacementException($"ball \"{id}\" is not in this game's ball set");
        }
        var others = new List<Vec3>();
        var balls = simulation.Balls;
        for (int j = 0; j < balls.Length; j++)
        {
            if (j != index && !balls[j].IsOutOfPlay)
            {
                others.Add(balls[j].Position);
            }
        }
        double r = simulation.BallRadius;
        double spot = simulation.Table.HalfLength / 2;
        double limit = simulation.Table.HalfLength - r;
        double x = Placement.FreeOnLongAxis(r, others, spot, +1);
        if (x > limit + Placement.Tolerance)
        {
            x = Placement.FreeOnLongAxis(r, others, spot, -1);
            if (x < -limit - Placement.Tolerance)
            {
                throw new Physics.PlacementException($"ball \"{id}\" cannot be spotted: the long axis has no free place");
            }
        }
        var position = new Vec3(x, 0, r);
        simulation.PlaceBall(id, position);
        return position;
    }

    /// <summary>The referee of the game on <paramref name="table"/> with balls of radius <paramref name="ballRadius"/> (m).</summary>
    public abstract IReferee Referee(TableSpec table, double ballRadius);

    /// <summary>True when the game calls its shots (every shot but the break).</summary>
    public virtual bool CallsShots => true;

    /// <summary>True when the shooter must call the shot (ball and pocket, or a safety) before it.</summary>
    public bool NeedsCall(GameState state)
    {
        ArgumentNullException.ThrowIfNull(state);
        return CallsShots && state.Shot > 0;
    }

    /// <summary>True when the game has a push-out (9-ball and 10-ball).</summary>
    public virtual bool HasPushOut => false;

    /// <summary>True when the shooter of <paramref name="state"/> may declare a push-out (the shot after the break).</summary>
    public bool MayPushOut(GameState state)
    {
        ArgumentNullException.ThrowIfNull(state);
        return HasPushOut && state.Shot == 1;
    }

    /// <summary>True when players own groups of balls (8-ball's solids and stripes).</summary>
    public virtual bool HasGroups => false;

    /// <summary>
    /// True when three fouls in a row have a consequence (a loss in 9-ball and 10-ball, a penalty
    /// in 14.1), which ends the count: a player then has at most two fouls in a row before a shot.
    /// Without it (8-ball) the count only grows.
    /// </summary>
    public virtual bool HasThreeFouls => true;

    /// <summary>True when the computer player (<see cref="Ai.ShotPlanner"/>) plays the game.</summary>
    public virtual bool HasComputerPlayer => true;

    /// <summary>
    /// True when the game has a ball on and scores each shot (snooker): its game blocks carry
    /// ball_on, free_ball and misses_in_row, its rulings points, penalty, foul_and_miss and free_ball.
    /// </summary>
    public virtual bool HasBallOn => false;

    /// <summary>True when the game keeps a score with a target (14.1).</summary>
    public virtual bool HasScore => false;

    /// <summary>
    /// The balls the shooter of <paramref name="state"/> may hit first, from the object balls on
    /// the table (rules.md), in number order.
    /// </summary>
    public abstract IReadOnlyList<BallId> LegalTargets(GameState state, IEnumerable<BallId> objectBalls);

    /// <summary>
    /// The balls the shooter must still pot to win from <paramref name="objectBalls"/>: the legal
    /// targets, and the game ball where it is not yet a target (8-ball's 8).
    /// </summary>
    public virtual IReadOnlyList<BallId> StillToPot(GameState state, IEnumerable<BallId> objectBalls) => LegalTargets(state, objectBalls);

    /// <summary>True when the shooter may call <paramref name="ball"/> for a pot.</summary>
    public virtual bool MayCall(GameState state, BallId ball) => true;

    /// <summary>
    /// What a shot adds to the shooter's break, the score of one visit to the table (a visit: the
    /// shots of one player from coming to the table until a shot that does not keep them there).
    /// Pool: the object balls pocketed on a legal shot that stay down (balls; in 14.1 each is a
    /// point); a ball spotted again (14.1's balls of a shot that missed its call, 10-ball's 10
    /// pocketed uncalled) and a foul add nothing. Snooker overrides it with the shot's points.
    /// </summary>
    public virtual int BreakValue(Ruling ruling)
    {
        ArgumentNullException.ThrowIfNull(ruling);
        return ruling.Legal ? ruling.Pocketed.Count(b => !ruling.Spot.Contains(b)) : 0;
    }

    /// <summary>What <see cref="BreakValue"/> counts: "balls" in pool, "points" in snooker.</summary>
    public virtual string BreakUnit => "balls";

    /// <summary>
    /// The word for one visit's score on the scoreboard and the result panel: "run" in pool (the
    /// balls of one visit), "break" in snooker (its points).
    /// </summary>
    public virtual string BreakWord => "run";

    /// <summary>The word for one game of a match: "game", snooker's "frame".</summary>
    public virtual string GameWord => "game";

    /// <summary>The game named in a sentence: "the 8-ball game", snooker's "the frame".</summary>
    public virtual string TheGame => $"the {ShortName} game";

    /// <summary>
    /// The points still on the table for the shooter of <paramref name="state"/> with
    /// <paramref name="objectBalls"/> on it, or null where a game does not count them (pool).
    /// </summary>
    public virtual int? PointsRemaining(GameState state, IReadOnlyCollection<BallId> objectBalls) => null;

    /// <summary>
    /// True where the game knows snookers (<see cref="HasSnookers"/>) and <paramref name="player"/>
    /// is behind by more than the points remaining (<see cref="PointsRemaining"/>).
    /// </summary>
    public bool NeedsSnookers(GameState state, int player, IReadOnlyCollection<BallId> objectBalls)
    {
        ArgumentNullException.ThrowIfNull(state);
        return HasSnookers && PointsRemaining(state, objectBalls) is int left && state.Score[1 - player] - state.Score[player] > left;
    }

    /// <summary>
    /// The visits to the table in <paramref name="shots"/> (each shot's shooter and ruling, in
    /// order), each with its break by <see cref="BreakValue"/>. A visit is the shots of one player
    /// from coming to the table until a shot that does not keep them there, whoever plays next:
    /// the offender put back in after a foul starts a new one. The last visit is open when its
    /// last shot kept the shooter at the table (the visit now at the table, or a game cut off).
    /// </summary>
    public IEnumerable<Visit> Visits(IEnumerable<(int Shooter, Ruling Ruling)> shots)
    {
        ArgumentNullException.ThrowIfNull(shots);
        return Walk(shots);

        IEnumerable<Visit> Walk(IEnumerable<(int Shooter, Ruling Ruling)> all)
        {
            int? visitor = null;
            int points = 0, count = 0;
            foreach (var (shooter, ruling) in all)
            {
                if (visitor != shooter)
                {
                    // A shot by the other player without the visit having ended cannot happen; end it anyway.
                    if (visitor is int open)
                    {
                        yield return new Visit(open, count, points, false);
                    }
                    (visitor, points, count) = (shooter, 0, 0);
                }
                points += BreakValue(ruling);
                count++;
                if (!ruling.Continue)
                {
                    yield return new Visit(shooter, count, points, false);
                    visitor = null;
                }
            }
            if (visitor is int last)
            {
                yield return new Visit(last, count, points, true);
            }
        }
    }

    /// <summary>Shots after which a game between computers is abandoned without a winner.</summary>
    public virtual int MaxShots(GameState start) => 400;

    /// <summary>
    /// The state and table work that follow when the ruling's next shooter takes
    /// <paramref name="option"/>.
    /// </summary>
    /// <exception cref="ArgumentException">When the ruling does not offer the option.</exception>
    public OptionOutcome Choose(Ruling ruling, RefereeOption option)
    {
        ArgumentNullException.ThrowIfNull(ruling);
        if (!ruling.Options.Contains(option))
        {
            throw new ArgumentException($"the ruling offers no \"{(TryWordOf(option, out string? word) ? word : option.ToString())}\" (it offers {string.Join(", ", ruling.Options.Select(WordOf))})", nameof(option));
        }
        var next = ruling.Next;
        return option switch
        {
            RefereeOption.Rerack => new OptionOutcome(Rerack(next), true, []),
            RefereeOption.PassBack => new OptionOutcome(next with { Shooter = next.Incoming, BallInHand = BallInHand.None }, false, ruling.Spot),
            // The offender plays again from where the balls lie (from hand after an in-off); a free ball is the incoming player's only.
            RefereeOption.PutBack => new OptionOutcome(PutBack(next), false, ruling.Spot),
            RefereeOption.Accept or RefereeOption.SpotEight or RefereeOption.Shoot or RefereeOption.Play => new OptionOutcome(next, false, ruling.Spot),
            _ => ChooseOther(ruling, option, next),
        };
    }

    private static readonly (RefereeOption, string)[] NoOptions = [];

    /// <summary>
    /// The options the game's referee offers, each with its word in files (scene-format.md
    /// "options", a game record's "choice"), e.g. (<see cref="RefereeOption.PassBack"/>, "pass-back"):
    /// the game writes and parses its own words. None by default.
    /// </summary>
    public virtual IReadOnlyList<(RefereeOption Option, string Word)> OptionWords => NoOptions;

    /// <summary>True, with its word, when the game offers <paramref name="option"/>.</summary>
    public bool TryWordOf(RefereeOption option, [System.Diagnostics.CodeAnalysis.NotNullWhen(true)] out string? word)
    {
        foreach (var (o, w) in OptionWords)
        {
            if (o == option)
            {
                word = w;
                return true;
            }
        }
        word = null;
        return false;
    }

    /// <summary>The word of <paramref name="option"/>, one of the game's (<see cref="OptionWords"/>).</summary>
    /// <exception cref="ArgumentOutOfRangeException">When the game offers no such option.</exception>
    public string WordOf(RefereeOption option) => TryWordOf(option, out string? word)
        ? word
        : throw new ArgumentOutOfRangeException(nameof(option), option, $"{Name} offers no such option");

    /// <summary>Parses one of the game's option words (<see cref="OptionWords"/>).</summary>
    public bool TryParseOption(string? word, out RefereeOption option)
    {
        foreach (var (o, w) in OptionWords)
        {
            if (w == word)
            {
                option = o;
                return true;
            }
        }
        option = default;
        return false;
    }

    /// <summary>
    /// The words after the next shooter of a ruling took <paramref name="option"/>, with
    /// <paramref name="state"/> the state it leads to, e.g. "Put back: Ben plays again.".
    /// </summary>
    public virtual string ChoiceMessage(RefereeOption option, GameState state)
    {
        ArgumentNullException.ThrowIfNull(state);
        return option switch
        {
            RefereeOption.Play => $"{state.ShooterName} plays the balls as they lie.",
            RefereeOption.PutBack => $"Put back: {state.ShooterName} plays again.",
            RefereeOption.Replace => $"The balls are replaced: {state.ShooterName} plays again.",
            _ => $"{WordOf(option)}: {state.ShooterName} to shoot.",
        };
    }

    /// <summary>The breaker's part of the start of a game that <paramref name="breaker"/> (0 or 1) breaks: by default they shoot first.</summary>
    public virtual GameState BrokenBy(GameState start, int breaker)
    {
        ArgumentNullException.ThrowIfNull(start);
        return start with { Shooter = breaker };
    }

    /// <summary>What a game's own option (snooker's <see cref="RefereeOption.Replace"/>, three-cushion's <see cref="RefereeOption.SpotBreak"/>) leads to; by default the table as it lies.</summary>
    protected virtual OptionOutcome ChooseOther(Ruling ruling, RefereeOption option, GameState next)
    {
        ArgumentNullException.ThrowIfNull(ruling);
        return new OptionOutcome(next, false, ruling.Spot);
    }

    /// <summary>The state before the break of a rerack the ruling's next shooter chose: by default the chooser breaks.</summary>
    protected virtual GameState Rerack(GameState next) => next with { Shot = 0, BallInHand = BallInHand.None };

    /// <summary>The state when the ruling's next shooter puts the offender back in: by default the offender plays from where the balls lie.</summary>
    protected virtual GameState PutBack(GameState next) => next with { Shooter = next.Incoming };

    private static readonly string[] NoFields = [];

    /// <summary>None by default: a game without a part of its own (9-ball, 14.1) keeps only the common state.</summary>
    public virtual GameStatePart? StartPart => null;

    /// <inheritdoc />
    public virtual IReadOnlyList<string> PartFields => NoFields;

    /// <inheritdoc />
    public virtual GameStatePart? ReadPart(Scenes.GameBlockFields block) => StartPart;

    /// <summary>Pool's call of a ball and a pocket by default (<see cref="Scenes.GameBlockReader.ReadPocketCall"/>).</summary>
    public virtual Call ReadCall(JsonElement call, Scenes.GameBlockFields block) => Scenes.GameBlockReader.ReadPocketCall(call, this, block);

    /// <summary>Nothing by default.</summary>
    public virtual void WritePart(Utf8JsonWriter writer, GameState state, GameBlockSlot slot)
    {
    }

    /// <summary>Nothing by default.</summary>
    public virtual void WriteRulingFields(Utf8JsonWriter writer, Ruling ruling)
    {
    }

    /// <summary>
    /// Racks <paramref name="balls"/> again during a game (14.1's rerack of fourteen) on the balls
    /// at rest (<paramref name="table"/>); returns the balls after the rerack and the ball in hand
    /// it gives (a cue ball in the rack's way is taken up), or null when it gives none.
    /// </summary>
    /// <exception cref="InvalidOperationException">For a game without reracks during play.</exception>
    public virtual (BallLayout Balls, BallInHand? BallInHand) RerackDuringPlay(BallLayout table, IReadOnlyList<BallId> balls, TableSpec tableSpec, double ballRadius, int seed) =>
        throw new InvalidOperationException($"{Name} has no rerack during play");

    /// <summary>What the HUD shows as <paramref name="player"/>'s target with <paramref name="objectBalls"/> on the table.</summary>
    public abstract HudTarget Target(GameState state, int player, IReadOnlyCollection<BallId> objectBalls);

    /// <summary>
    /// True when the shooter of <paramref name="state"/> nominates a ball without a pocket before
    /// the shot (snooker's colour after a red, and a free ball); false in the pool games.
    /// </summary>
    public virtual bool Nominates(GameState state) => false;

    /// <summary>
    /// The call of a shot whose first ball is <paramref name="ball"/> where the game nominates
    /// (<see cref="Nominates"/>): the nomination of that ball when the shooter may nominate it,
    /// else null (no call).
    /// </summary>
    public Call? Nomination(GameState state, BallId ball) => Nominates(state) && MayCall(state, ball) ? Call.Nominate(ball) : null;

    /// <summary>
    /// True when the break is a power break into the rack (pool); false where the first shot is
    /// an opening safety played like any other (snooker's break-off).
    /// </summary>
    public virtual bool PowerBreak => true;

    /// <summary>True when the shot to play in <paramref name="state"/> is a power break: the rack's first shot in a game with one (<see cref="PowerBreak"/>).</summary>
    public bool IsPowerBreak(GameState state)
    {
        ArgumentNullException.ThrowIfNull(state);
        return state.Shot == 0 && PowerBreak;
    }

    /// <summary>How the computer player weighs the game (<see cref="Ai.PlannerPolicy"/>): pool's by default.</summary>
    public virtual Ai.PlannerPolicy Policy => Ai.PlannerPolicy.Pool;

    /// <summary>True when the rules know the snooker (a player with no straight line to any ball on: snooker's miss and free ball).</summary>
    public virtual bool HasSnookers => false;

    /// <summary>Orders balls by number.</summary>
    protected static List<BallId> Ordered(IEnumerable<BallId> balls) => [.. balls.OrderBy(b => b.Value)];
}
