using Billiards.Core.Setup;
using Billiards.Core.Balls;
using Billiards.Core.Physics;
using Billiards.Core.Table;

namespace Billiards.Core.Rules;

/// <summary>What every referee reads off a shot record (rules.md, "Words").</summary>
internal sealed class ShotFacts
{
    public ShotFacts(GameState before, ShotRecord shot, TableSpec table, double radius)
    {
        // The shooter's cue ball; every other ball is an object ball to them.
        var cue = Ruleset.For(before.Rules).CueBall(before);
        var events = shot.Events;
        int contact = shot.FirstContactIndex;
        FirstContact = shot.FirstContact;
        var cushioned = new HashSet<BallId>();
        for (int i = 0; i < events.Length; i++)
        {
            ref readonly var e = ref events[i];
            switch (e.Kind)
            {
                case EventKind.BallCushion:
                    cushioned.Add(e.A);
                    RailAfterContact |= contact >= 0 && i > contact;
                    break;
                case EventKind.BallPocket when e.A == cue:
                    Scratch = true;
                    break;
                case EventKind.BallOffTable when e.A == cue:
                    CueOffTable = true;
                    break;
                case EventKind.BallOffTable:
                    OffTable.Add(e.A);
                    break;
                case EventKind.BallPocket when !PocketOf.ContainsKey(e.A):
                    PocketOf[e.A] = table.Pockets.Id(e.Feature);
                    Pocketed.Add(e.A);
                    RailAfterContact |= contact >= 0 && i > contact;
                    break;
            }
        }
        CueToCushion = cushioned.Contains(cue);
        ObjectBallsToCushion = cushioned.Count - (CueToCushion ? 1 : 0);

        var ids = shot.Ids;
        var after = shot.BallsAfter;
        OnTableBefore = new BallNumbers(ids.Length);
        OnTableAfter = new BallNumbers(ids.Length);
        for (int i = 0; i < ids.Length; i++)
        {
            if (ids[i] == cue)
            {
                continue;
            }
            if (!after[i].IsOutOfPlay)
            {
                OnTableAfter.Add(ids[i].Value);
                OnTableBefore.Add(ids[i].Value);
            }
            else if (PocketOf.ContainsKey(ids[i]) || OffTable.Contains(ids[i]))
            {
                OnTableBefore.Add(ids[i].Value);
            }
        }
        BadPlacement = IsBadPlacement(before, shot, table, radius);
    }

    /// <summary>The first object ball the cue ball touched, or null.</summary>
    public BallId? FirstContact { get; }

    /// <summary>The cue ball was pocketed.</summary>
    public bool Scratch { get; }

    /// <summary>The cue ball left the table over a rail.</summary>
    public bool CueOffTable { get; }

    /// <summary>Object balls that left the table over a rail on the shot, in the order they left.</summary>
    public List<BallId> OffTable { get; } = [];

    /// <summary>Object balls pocketed on the shot, in the order they dropped.</summary>
    public List<BallId> Pocketed { get; } = [];

    /// <summary>The pocket of each object ball pocketed on the shot.</summary>
    public Dictionary<BallId, PocketId> PocketOf { get; } = [];

    /// <summary>After the first contact a ball touched a cushion or an object ball was pocketed.</summary>
    public bool RailAfterContact { get; }

    /// <summary>The cue ball touched a cushion.</summary>
    public bool CueToCushion { get; }

    /// <summary>How many different object balls touched a cushion.</summary>
    public int ObjectBallsToCushion { get; }

    /// <summary>Numbers of the object balls on the table before the shot.</summary>
    public BallNumbers OnTableBefore { get; }

    /// <summary>Numbers of the object balls on the table after the shot.</summary>
    public BallNumbers OnTableAfter { get; }

    /// <summary>The ball in hand was placed outside its region or on a ball.</summary>
    public bool BadPlacement { get; }

    /// <summary>The lowest-numbered object ball on the table before the shot, or null.</summary>
    public BallId? Lowest => OnTableBefore.Count > 0 ? new BallId(OnTableBefore.Min) : null;

    /// <summary>The ball went into the called pocket on this shot.</summary>
    public bool Made(Call? call) =>
        call is { IsSafety: false } && PocketOf.TryGetValue(call.Ball, out var pocket) && pocket == call.Pocket;

    /// <summary>
    /// The break is placed behind the head string; later shots where the state says. Overlap is
    /// checked against the balls that took no part in the shot, which still stand where they stood
    /// when the cue ball was placed.
    /// </summary>
    private static bool IsBadPlacement(GameState before, ShotRecord shot, TableSpec table, double radius)
    {
        var region = before.Shot == 0 ? BallInHand.Kitchen : before.BallInHand;
        if (region == BallInHand.None || before.Placement is not { } p)
        {
            return false;
        }
        // The head spot lies on the head string: a centre on the string counts as behind it (ours).
        if (!Placement.FitsOnTable(table, radius, p, region == BallInHand.Kitchen ? PlacementRegion.Kitchen : PlacementRegion.Table))
        {
            return true;
        }
        var moved = new HashSet<BallId>();
        foreach (ref readonly var e in shot.Events)
        {
            moved.Add(e.A);
            moved.Add(e.B);
        }
        var ids = shot.Ids;
        var after = shot.BallsAfter;
        for (int i = 0; i < ids.Length; i++)
        {
            if (ids[i] != shot.CueBall && !moved.Contains(ids[i]) && !after[i].IsOutOfPlay
                && Placement.Overlaps(radius, after[i].Position, p))
            {
                return true;
            }
        }
        return false;
    }
}
