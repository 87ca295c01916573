using Billiards.Core.Setup;

namespace Billiards.Core.Rules;

/// <summary>Where a cue ball in hand may be placed, as the placement test names the region.</summary>
public static class BallInHandRegions
{
    /// <summary>The placement region of <paramref name="hand"/>: the kitchen, snooker's D, else the whole bed (also for no ball in hand).</summary>
    public static PlacementRegion Region(this BallInHand hand) => hand switch
    {
        BallInHand.Kitchen => PlacementRegion.Kitchen,
        BallInHand.D => PlacementRegion.D,
        _ => PlacementRegion.Table,
    };
}
