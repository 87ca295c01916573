namespace Billiards.Core.Physics;

/// <summary>
/// A cloth as the game offers it: its sliding friction mu_s and rolling resistance mu_r, within the
/// ranges of Alciatore's typical pool physical properties (mu_s 0.15-0.4, typically 0.2; mu_r
/// 0.005-0.015). "standard" is the table's own cloth (its preset's, <see cref="Balls.BallSet.DefaultParams"/>:
/// pool's typical cloth, or snooker's as measured), which it leaves as it is.
/// </summary>
/// <param name="Name">The cloth's name in the menu and the settings file.</param>
/// <param name="MuS">Sliding friction, ball-cloth.</param>
/// <param name="MuR">Rolling resistance.</param>
public sealed record Cloth(string Name, double MuS, double MuR)
{
    /// <summary>A heavy, napped cloth: balls slide and roll out sooner.</summary>
    public static Cloth Slow { get; } = new("slow", 0.3, 0.015);

    /// <summary>The table's own cloth (its frictions here are pool's, for show; <see cref="On"/> keeps the table's).</summary>
    public static Cloth Standard { get; } = new("standard", PhysicsParams.Pool.MuS, PhysicsParams.Pool.MuR);

    /// <summary>A new worsted tournament cloth: balls run far.</summary>
    public static Cloth Fast { get; } = new("fast", 0.15, 0.005);

    /// <summary>
    /// The heated cloth of a carom match table (three-cushion's, rules.md): a worsted carom cloth
    /// on a slate heated a few degrees above the room, which keeps the cloth dry. mu_s 0.2: the
    /// cloth's sliding friction is the fabric's, and a worsted cloth sits at Alciatore's typical
    /// 0.2 (TP A-14, "typical physical properties": mu_s 0.15-0.4). mu_r 0.007: a dry, tight cloth
    /// without nap rolls further than pool's 0.01 (the model's default); 0.007 is ours, inside
    /// Alciatore's 0.005-0.015 and above the "fast" pool cloth's 0.005. What it changes, measured
    /// with <c>simulate</c> (the white from the head spot at 30 deg, the carom table): at cue speeds
    /// of 2, 3 and 4 m/s the ball makes 4, 5 and 7 cushions as on mu_r 0.01 (the cushions take most
    /// of its speed) and rolls 9.6, 12.0 and 11.0 s instead of 7.9, 9.2 and 9.0 s: the long slow
    /// finish of a position shot on a match table.
    /// </summary>
    public static Cloth Heated { get; } = new("heated", 0.2, 0.007);

    /// <summary>Every cloth, slowest first (the heated carom cloth last).</summary>
    public static IReadOnlyList<Cloth> All { get; } = [Slow, Standard, Fast, Heated];

    /// <summary>The cloth called <paramref name="name"/>, or null.</summary>
    public static Cloth? Find(string? name) => All.FirstOrDefault(c => c.Name == name);

    /// <summary>The parameters with this cloth's frictions.</summary>
    public PhysicsParams On(PhysicsParams parameters)
    {
        ArgumentNullException.ThrowIfNull(parameters);
        return ReferenceEquals(this, Standard) ? parameters : parameters with { MuS = MuS, MuR = MuR };
    }
}
