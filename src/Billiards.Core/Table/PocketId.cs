namespace Billiards.Core.Table;

/// <summary>
/// Identity of a pocket of a table: its index in the table's <see cref="PocketSet"/> and its name
/// in scene and result files ("head-left", ..., scene-format.md). Made by the table's set
/// (<see cref="PocketSet.Id"/>, <see cref="PocketSet.TryParse"/>); two ids are equal when both
/// index and name are.
/// </summary>
/// <param name="Index">Index in the table's pocket set (the value of <see cref="Balls.BallState.Pocket"/>), -1 for none.</param>
/// <param name="Name">The pocket's name in files, "none" for <see cref="None"/>.</param>
public readonly record struct PocketId(int Index, string Name)
{
    /// <summary>No pocket (a ball in play, a safety's call, or a pocketless table).</summary>
    public static PocketId None { get; } = new(-1, "none");

    /// <summary>False for <see cref="None"/>.</summary>
    public bool IsPocket => Index >= 0;

    /// <summary>The pocket's name as scene and result files write it ("none" for <see cref="None"/>).</summary>
    public string ToName() => Name ?? "none";

    /// <summary>The name, for messages.</summary>
    public override string ToString() => ToName();
}
