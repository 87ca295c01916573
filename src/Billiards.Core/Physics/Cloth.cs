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

    /// <summary>Every cloth, slowest first.</summary>
    public static IReadOnlyList<Cloth> All { get; } = [Slow, Standard, Fast];

    /// <summary>The cloth called <paramref name="name"/>, or null.</summary>
    public static Cloth? Find(string? name) => All.FirstOrDefault(c => c.Name == name);

    /// <summary>The parameters with this cloth's frictions.</summary>
    public PhysicsParams On(PhysicsParams parameters)
    {
        ArgumentNullException.ThrowIfNull(parameters);
        return ReferenceEquals(this, Standard) ? parameters : parameters with { MuS = MuS, MuR = MuR };
    }
}
