namespace Billiards.Core.Rules;

/// <summary>
/// A game by its name in files (rules.md), e.g. "eight-ball": the key of its ruleset in the
/// registry (<see cref="Ruleset.Register"/>). The five games the referee ships with are named
/// here; any other registered ruleset is a game too.
/// </summary>
/// <param name="Name">The game's name in files, e.g. "eight-ball".</param>
public readonly record struct GameRules(string Name)
{
    /// <summary>8-ball: solids and stripes, the 8 last, called shots.</summary>
    public static GameRules EightBall { get; } = new("eight-ball");

    /// <summary>9-ball: the lowest ball first, the 9 wins, push-out and three fouls.</summary>
    public static GameRules NineBall { get; } = new("nine-ball");

    /// <summary>10-ball: 9-ball's rules with called shots and the 10.</summary>
    public static GameRules TenBall { get; } = new("ten-ball");

    /// <summary>14.1 continuous (straight pool): called balls score a point each, reracks of 14.</summary>
    public static GameRules StraightPool { get; } = new("straight-pool");

    /// <summary>Snooker (WPBSA): reds and colours, points, fouls worth at least 4, free ball and the miss.</summary>
    public static GameRules Snooker { get; } = new("snooker");

    /// <summary>The game of that name (a test's data, a tool's argument); <see cref="RuleNames.TryParseGame"/> checks it is registered.</summary>
    public static implicit operator GameRules(string name) => new(name);

    /// <summary>The game of that name.</summary>
    public static GameRules FromString(string name) => new(name);

    /// <inheritdoc />
    public override string ToString() => Name;
}

/// <summary>A group of 8-ball.</summary>
public enum BallGroup
{
    /// <summary>Pool's solids (1-7).</summary>
    Solids,
    /// <summary>Pool's stripes (9-15).</summary>
    Stripes,
}

/// <summary>Which balls make up an 8-ball group.</summary>
public static class BallGroups
{
    /// <summary>True for a ball of <paramref name="group"/> in pool's set (<see cref="Balls.BallSet.Group"/>).</summary>
    public static bool Contains(this BallGroup group, Balls.BallId ball) => Balls.BallSet.Pool.Group(group.ToName()).Contains(ball);
}

/// <summary>Where the next shooter may place the cue ball.</summary>
public enum BallInHand
{
    /// <summary>No ball in hand: the cue ball stays where it lies.</summary>
    None,
    /// <summary>Anywhere on the bed.</summary>
    Table,
    /// <summary>Behind the head string (x &lt; -L/4).</summary>
    Kitchen,
    /// <summary>Snooker: in the D (<see cref="Table.SnookerTable.InD"/>).</summary>
    D,
}

/// <summary>A choice the incoming player (the ruling's next shooter) may make after a shot.</summary>
public enum RefereeOption
{
    /// <summary>Accept the table as it lies and shoot.</summary>
    Accept,
    /// <summary>Rack the balls again and break.</summary>
    Rerack,
    /// <summary>Spot the 8 pocketed on the break and go on.</summary>
    SpotEight,
    /// <summary>Shoot from the position a push-out left.</summary>
    Shoot,
    /// <summary>Hand the table back to the player who pushed out.</summary>
    PassBack,
    /// <summary>Snooker: take the table as it lies after a foul and play.</summary>
    Play,
    /// <summary>Snooker: the offender plays again from where the balls lie.</summary>
    PutBack,
    /// <summary>Snooker, after a foul and a miss: the balls go back to where they were before the shot and the offender plays again.</summary>
    Replace,
    /// <summary>Three-cushion: the shooter's ball is frozen to a ball; all three are spotted as for the break.</summary>
    SpotBreak,
}

/// <summary>The referee's codes for what went wrong on a shot (rules.md).</summary>
public enum Foul
{
    /// <summary>Ball in hand placed outside its region or overlapping a ball.</summary>
    BadPlacement,
    /// <summary>The cue ball was pocketed (a scratch).</summary>
    CueBallPocketed,
    /// <summary>The cue ball touched no object ball.</summary>
    NoContact,
    /// <summary>The first contact was not a legal target.</summary>
    WrongBallFirst,
    /// <summary>After a legal first contact no ball was pocketed and none touched a cushion.</summary>
    NoRail,
    /// <summary>The break did not meet the game's requirement.</summary>
    BadBreak,
    /// <summary>8-ball: the 8 pocketed while the shooter's group was on the table (loss).</summary>
    EightBallEarly,
    /// <summary>8-ball: the 8 pocketed on a shot with a foul (loss).</summary>
    EightBallFoul,
    /// <summary>8-ball: the 8 pocketed in another pocket than the one called (loss).</summary>
    EightBallUncalled,
    /// <summary>Three fouls in a row: a loss in 9-ball and 10-ball, -15 points in 14.1.</summary>
    ThreeFouls,
    /// <summary>A ball (cue or object) left the table over a rail (a ball-off-table event).</summary>
    BallOffTable,
    /// <summary>8-ball: the 8 left the table (loss).</summary>
    EightBallOffTable,
    /// <summary>Snooker: a ball not on was potted.</summary>
    WrongBallPotted,
    /// <summary>Snooker: the cue ball left the bed and passed over a ball before it first struck one.</summary>
    JumpShot,
    /// <summary>Snooker: the third foul and a miss in a row with a full ball view (loss of the frame).</summary>
    ThreeMisses,
    /// <summary>Snooker: the striker who played a free ball left the opponent snookered behind it (ours: the code's name).</summary>
    SnookeredByFreeBall,
    /// <summary>Three-cushion: the ball struck was not the shooter's cue ball.</summary>
    WrongCueBall,
    /// <summary>Three-cushion: the break did not contact the red first.</summary>
    RedNotFirstOnBreak,
}

/// <summary>
/// The shooter's call: a ball and a pocket, a safety (the cue ball and
/// <see cref="Table.PocketId.None"/>), or snooker's nomination of a ball without a pocket.
/// </summary>
/// <param name="Ball">The called ball (<see cref="Balls.BallId.None"/> for a safety).</param>
/// <param name="Pocket">The called pocket, or <see cref="Table.PocketId.None"/> for a safety or a nomination.</param>
public sealed record Call(Balls.BallId Ball, Table.PocketId Pocket)
{
    /// <summary>A declared safety: no ball is called.</summary>
    public static Call Safety { get; } = new(Balls.BallId.None, Table.PocketId.None);

    /// <summary>True for a declared safety.</summary>
    public bool IsSafety => !Pocket.IsPocket && Ball == Balls.BallId.None;

    /// <summary>Snooker: the striker nominates <paramref name="ball"/> (a colour after a red, or a free ball), no pocket.</summary>
    public static Call Nominate(Balls.BallId ball) => new(ball, Table.PocketId.None);

    /// <summary>True for snooker's nomination of a ball without a pocket.</summary>
    public bool IsNomination => !Pocket.IsPocket && Ball != Balls.BallId.None;
}

/// <summary>The names scene and result files use for the referee's enums (scene-format.md).</summary>
public static class RuleNames
{
    private static readonly string[] Groups = ["solids", "stripes"];
    private static readonly string[] Hands = ["none", "table", "kitchen", "d"];
    private static readonly string[] Fouls =
    [
        "bad-placement", "cue-ball-pocketed", "no-contact", "wrong-ball-first", "no-rail", "bad-break",
        "eight-ball-early", "eight-ball-foul", "eight-ball-uncalled", "three-fouls",
        "ball-off-table", "eight-ball-off-table",
        "wrong-ball-potted", "jump-shot", "three-misses", "snookered-by-free-ball",
        "wrong-cue-ball", "red-not-first-on-break",
    ];

    /// <summary>The names of the registered games, in the order they were registered (the shipped five first).</summary>
    public static IReadOnlyList<string> GameNames => [.. Ruleset.All.Select(r => r.Name)];

    /// <summary>The game's name in files, e.g. "eight-ball".</summary>
    public static string ToName(this GameRules rules) => rules.Name;

    /// <summary>"solids" or "stripes".</summary>
    public static string ToName(this BallGroup group) => Groups[(int)group];

    /// <summary>"none", "table", "kitchen" or "d" (results write null for none).</summary>
    public static string ToName(this BallInHand hand) => Hands[(int)hand];

    /// <summary>
    /// The option's word in files, e.g. "pass-back", as the registered game that offers it words it
    /// (<see cref="Ruleset.OptionWords"/>); within one game <see cref="Ruleset.WordOf"/> says it.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException">For an option no registered game offers.</exception>
    public static string ToName(this RefereeOption option)
    {
        foreach (var ruleset in Ruleset.All)
        {
            if (ruleset.TryWordOf(option, out string? word))
            {
                return word;
            }
        }
        throw new ArgumentOutOfRangeException(nameof(option), option, "no registered game offers the option");
    }

    /// <summary>The foul's code, e.g. "cue-ball-pocketed".</summary>
    public static string ToName(this Foul foul) => Fouls[(int)foul];

    /// <summary>Parses the name of a registered game.</summary>
    public static bool TryParseGame(string? name, out GameRules rules)
    {
        rules = name is not null && Ruleset.Find(name) is { } ruleset ? ruleset.Game : GameRules.EightBall;
        return name is not null && Ruleset.Find(name) is not null;
    }

    /// <summary>Parses a group name.</summary>
    public static bool TryParseGroup(string? name, out BallGroup group) => TryParse(Groups, name, out group);

    /// <summary>Parses "table", "kitchen" or "d" (not "none").</summary>
    public static bool TryParseBallInHand(string? name, out BallInHand hand) =>
        TryParse(Hands, name, out hand) && hand != BallInHand.None;

    /// <summary>Parses an option's word of any registered game; <see cref="Ruleset.TryParseOption"/> parses one game's.</summary>
    public static bool TryParseOption(string? name, out RefereeOption option)
    {
        foreach (var ruleset in Ruleset.All)
        {
            if (ruleset.TryParseOption(name, out option))
            {
                return true;
            }
        }
        option = default;
        return false;
    }

    /// <summary>Parses a foul code.</summary>
    public static bool TryParseFoul(string? name, out Foul foul) => TryParse(Fouls, name, out foul);

    private static bool TryParse<T>(string[] names, string? name, out T value) where T : struct, Enum
    {
        int i = Array.IndexOf(names, name);
        value = (T)(object)Math.Max(i, 0);
        return i >= 0;
    }
}
