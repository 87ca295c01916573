namespace Billiards.Core.Table;

/// <summary>
/// A pocket of a six-pocket table, the same under every model. Left and right are as seen from the
/// head rail looking towards the foot rail (scene-format.md).
/// </summary>
public enum PocketId : sbyte
{
    /// <summary>No pocket (a ball in play, or a pocketless table).</summary>
    None = -1,
    /// <summary>The corner pocket at the head rail, on the left.</summary>
    HeadLeft = 0,
    /// <summary>The corner pocket at the head rail, on the right.</summary>
    HeadRight = 1,
    /// <summary>The side pocket on the left.</summary>
    SideLeft = 2,
    /// <summary>The side pocket on the right.</summary>
    SideRight = 3,
    /// <summary>The corner pocket at the foot rail, on the left.</summary>
    FootLeft = 4,
    /// <summary>The corner pocket at the foot rail, on the right.</summary>
    FootRight = 5,
}

/// <summary>Names of the pockets as scene and result files write them.</summary>
public static class PocketIds
{
    private static readonly string[] Names = ["head-left", "head-right", "side-left", "side-right", "foot-left", "foot-right"];

    /// <summary>The six pockets in index order.</summary>
    public static IReadOnlyList<PocketId> All { get; } =
        [PocketId.HeadLeft, PocketId.HeadRight, PocketId.SideLeft, PocketId.SideRight, PocketId.FootLeft, PocketId.FootRight];

    /// <summary>"head-left", ..., "foot-right"; "none" for <see cref="PocketId.None"/>.</summary>
    public static string ToName(this PocketId pocket) =>
        (uint)(int)pocket < (uint)Names.Length ? Names[(int)pocket] : "none";

    /// <summary>Parses a pocket name as written by <see cref="ToName"/> (not "none").</summary>
    public static bool TryParse(string? name, out PocketId pocket)
    {
        int i = Array.IndexOf(Names, name);
        pocket = i >= 0 ? (PocketId)i : PocketId.None;
        return i >= 0;
    }

    /// <summary>The pocket of a ball's <see cref="Balls.BallState.Pocket"/> index (-1 for none).</summary>
    public static PocketId FromIndex(int index) => (uint)index < (uint)Names.Length ? (PocketId)index : PocketId.None;
}
