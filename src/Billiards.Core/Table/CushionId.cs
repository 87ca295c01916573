namespace Billiards.Core.Table;

/// <summary>
/// A cushion feature of a six-pocket table, the same under every model: the six rails, the
/// jaws of each pocket and the back wall of each pocket. Head is -x, foot +x; left and right as
/// seen from the head rail (scene-format.md). Each model maps its own features to these
/// (<see cref="Physics.Simulation.CushionOf"/>); results keep each model's feature names.
/// </summary>
public enum CushionId : sbyte
{
    /// <summary>No cushion (another kind of event).</summary>
    None = -1,
    /// <summary>The head rail (x = -L/2).</summary>
    Head = 0,
    /// <summary>The foot rail (x = +L/2).</summary>
    Foot = 1,
    /// <summary>The left long rail between the head-left corner and the left side pocket.</summary>
    LeftHead = 2,
    /// <summary>The left long rail between the left side pocket and the foot-left corner.</summary>
    LeftFoot = 3,
    /// <summary>The right long rail between the head-right corner and the right side pocket.</summary>
    RightHead = 4,
    /// <summary>The right long rail between the right side pocket and the foot-right corner.</summary>
    RightFoot = 5,
    /// <summary>A jaw of the head-left pocket.</summary>
    HeadLeftJaw = 6,
    /// <summary>A jaw of the head-right pocket.</summary>
    HeadRightJaw = 7,
    /// <summary>A jaw of the left side pocket.</summary>
    SideLeftJaw = 8,
    /// <summary>A jaw of the right side pocket.</summary>
    SideRightJaw = 9,
    /// <summary>A jaw of the foot-left pocket.</summary>
    FootLeftJaw = 10,
    /// <summary>A jaw of the foot-right pocket.</summary>
    FootRightJaw = 11,
    /// <summary>The back wall of the head-left pocket.</summary>
    HeadLeftBack = 12,
    /// <summary>The back wall of the head-right pocket.</summary>
    HeadRightBack = 13,
    /// <summary>The back wall of the left side pocket.</summary>
    SideLeftBack = 14,
    /// <summary>The back wall of the right side pocket.</summary>
    SideRightBack = 15,
    /// <summary>The back wall of the foot-left pocket.</summary>
    FootLeftBack = 16,
    /// <summary>The back wall of the foot-right pocket.</summary>
    FootRightBack = 17,
}

/// <summary>Helpers for <see cref="CushionId"/>.</summary>
public static class CushionIds
{
    private const int Rails = 6;
    private const int Pockets = 6;

    /// <summary>The jaw of <paramref name="pocket"/>.</summary>
    public static CushionId Jaw(PocketId pocket) => pocket == PocketId.None ? CushionId.None : (CushionId)(Rails + (int)pocket);

    /// <summary>The back wall of <paramref name="pocket"/>.</summary>
    public static CushionId Back(PocketId pocket) => pocket == PocketId.None ? CushionId.None : (CushionId)(Rails + Pockets + (int)pocket);

    /// <summary>True for one of the six rails.</summary>
    public static bool IsRail(this CushionId cushion) => cushion is >= CushionId.Head and <= CushionId.RightFoot;

    /// <summary>The pocket of a jaw or back wall; <see cref="PocketId.None"/> for a rail.</summary>
    public static PocketId PocketOf(this CushionId cushion) => cushion switch
    {
        >= CushionId.HeadLeftJaw and <= CushionId.FootRightJaw => (PocketId)((int)cushion - Rails),
        >= CushionId.HeadLeftBack and <= CushionId.FootRightBack => (PocketId)((int)cushion - Rails - Pockets),
        _ => PocketId.None,
    };

    /// <summary>
    /// The feature's name: a rail's as results write it ("head", "left-foot", ...), "head-left-jaw"
    /// for a jaw, "head-left-back" for a back wall; "none" for <see cref="CushionId.None"/>.
    /// </summary>
    public static string ToName(this CushionId cushion) => cushion switch
    {
        CushionId.Head => "head",
        CushionId.Foot => "foot",
        CushionId.LeftHead => "left-head",
        CushionId.LeftFoot => "left-foot",
        CushionId.RightHead => "right-head",
        CushionId.RightFoot => "right-foot",
        >= CushionId.HeadLeftJaw and <= CushionId.FootRightJaw => cushion.PocketOf().ToName() + "-jaw",
        >= CushionId.HeadLeftBack and <= CushionId.FootRightBack => cushion.PocketOf().ToName() + "-back",
        _ => "none",
    };
}
