using Billiards.Core.Table;

namespace Billiards.Core.Tests;

/// <summary>The pockets of a pool table by name, for tests that name one (a table's pockets are data: <see cref="TableSpec.Pockets"/>).</summary>
internal static class PoolPockets
{
    /// <summary>The pockets of the 9 ft pool table.</summary>
    public static PocketSet Set { get; } = TableSpec.FromPreset("pool-9ft").Pockets;

    /// <summary>Every pocket, in index order.</summary>
    public static IReadOnlyList<PocketId> All => Set.Ids;

    public static PocketId HeadLeft => Named("head-left");

    public static PocketId HeadRight => Named("head-right");

    public static PocketId SideLeft => Named("side-left");

    public static PocketId SideRight => Named("side-right");

    public static PocketId FootLeft => Named("foot-left");

    public static PocketId FootRight => Named("foot-right");

    private static PocketId Named(string name) => Set.TryParse(name, out var pocket) ? pocket : throw new ArgumentException(name);
}
