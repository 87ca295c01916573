using Billiards.Core.Table;

namespace Billiards.Core.Physics;

// The model-independent identities of the features events name.
public abstract partial class Simulation
{
    /// <summary>The model-independent identity of the cushion feature <paramref name="feature"/> of a <see cref="EventKind.BallCushion"/> event.</summary>
    public abstract CushionId CushionOf(int feature);

    /// <summary>The cushion a <see cref="EventKind.BallCushion"/> event hit, the same under every model; <see cref="CushionId.None"/> for other events.</summary>
    public CushionId Cushion(in SimEvent e) => e.Kind == EventKind.BallCushion ? CushionOf(e.Feature) : CushionId.None;

    /// <summary>The pocket of a <see cref="EventKind.BallPocket"/> event, one of the table's; <see cref="PocketId.None"/> for other events.</summary>
    public PocketId Pocket(in SimEvent e) => e.Kind == EventKind.BallPocket ? Table.Pockets.Id(e.Feature) : PocketId.None;
}
