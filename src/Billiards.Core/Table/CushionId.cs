namespace Billiards.Core.Table;

/// <summary>What a cushion feature is: a rail, a pocket's jaw, or a pocket's back wall.</summary>
public enum CushionKind : sbyte
{
    /// <summary>No cushion (another kind of event).</summary>
    None = 0,
    /// <summary>One of the six rail cushions.</summary>
    Rail = 1,
    /// <summary>A jaw of a pocket (both jaws of a pocket are one cushion here).</summary>
    Jaw = 2,
    /// <summary>The back wall of a pocket.</summary>
    Back = 3,
}

/// <summary>
/// A cushion feature, the same under every model: one of the six rails (the long rails split at
/// their middle), or the jaws or back wall of one of the table's pockets. Head is -x, foot +x;
/// left and right as seen from the head rail (scene-format.md). Each model maps its own features
/// to these (<see cref="Physics.Simulation.CushionOf"/>); results keep each model's feature names.
/// </summary>
/// <param name="Kind">Rail, jaw or back wall.</param>
/// <param name="Rail">The rail's index in <see cref="RailNames"/>, -1 for a jaw or back wall.</param>
/// <param name="Pocket">The pocket of a jaw or back wall, <see cref="PocketId.None"/> for a rail.</param>
public readonly record struct CushionId(CushionKind Kind, int Rail, PocketId Pocket)
{
    /// <summary>The rails' names as results write them, by rail index.</summary>
    public static IReadOnlyList<string> RailNames { get; } = ["head", "foot", "left-head", "left-foot", "right-head", "right-foot"];

    /// <summary>No cushion.</summary>
    public static CushionId None { get; } = new(CushionKind.None, -1, PocketId.None);

    /// <summary>The head rail (x = -L/2).</summary>
    public static CushionId Head { get; } = OfRail(0);

    /// <summary>The foot rail (x = +L/2).</summary>
    public static CushionId Foot { get; } = OfRail(1);

    /// <summary>The left long rail between the head end and the middle.</summary>
    public static CushionId LeftHead { get; } = OfRail(2);

    /// <summary>The left long rail between the middle and the foot end.</summary>
    public static CushionId LeftFoot { get; } = OfRail(3);

    /// <summary>The right long rail between the head end and the middle.</summary>
    public static CushionId RightHead { get; } = OfRail(4);

    /// <summary>The right long rail between the middle and the foot end.</summary>
    public static CushionId RightFoot { get; } = OfRail(5);

    /// <summary>The rail of index <paramref name="rail"/> (<see cref="RailNames"/>).</summary>
    public static CushionId OfRail(int rail) =>
        (uint)rail < 6 ? new(CushionKind.Rail, rail, PocketId.None) : throw new ArgumentOutOfRangeException(nameof(rail));

    /// <summary>The jaw of <paramref name="pocket"/>, or <see cref="None"/> for no pocket.</summary>
    public static CushionId Jaw(PocketId pocket) => pocket.IsPocket ? new(CushionKind.Jaw, -1, pocket) : None;

    /// <summary>The back wall of <paramref name="pocket"/>, or <see cref="None"/> for no pocket.</summary>
    public static CushionId Back(PocketId pocket) => pocket.IsPocket ? new(CushionKind.Back, -1, pocket) : None;

    /// <summary>True for one of the six rails.</summary>
    public bool IsRail => Kind == CushionKind.Rail;

    /// <summary>
    /// The feature's name: a rail's as results write it ("head", "left-foot", ...), "head-left-jaw"
    /// for a jaw, "head-left-back" for a back wall; "none" for <see cref="None"/>.
    /// </summary>
    public string ToName() => Kind switch
    {
        CushionKind.Rail => RailNames[Rail],
        CushionKind.Jaw => Pocket.ToName() + "-jaw",
        CushionKind.Back => Pocket.ToName() + "-back",
        _ => "none",
    };

    /// <summary>The name, for messages.</summary>
    public override string ToString() => ToName();
}
