using System.Globalization;

namespace Billiards.Core.Balls;

public sealed partial class BallSet
{
    /// <summary>Id of the first red ("red-1"); the reds follow it, then the colours from yellow to black.</summary>
    public const int FirstRed = 16;

    /// <summary>Number of reds in a snooker rack.</summary>
    public const int Reds = 15;

    /// <summary>The six colours of snooker in ascending value, 2 .. 7 (rules.md).</summary>
    public static IReadOnlyList<string> Colours => Sets.ColourNames;

    /// <summary>
    /// Snooker (WPBSA): the white cue ball ("cue", id 0 as in pool), fifteen reds "red-1" ..
    /// "red-15" worth 1 and the colours yellow 2, green 3, brown 4, blue 5, pink 6, black 7, all
    /// plain balls without numbers; the groups "reds" and "colours"; balls of 52.5 mm diameter and
    /// 142 g (the WPBSA fixes the diameter, 52.5 mm +- 0.05 mm, and asks only that the balls of a
    /// set weigh within 3 g of each other; 142 g is the usual weight of a tournament set).
    /// </summary>
    public static BallSet Snooker => Sets.Snooker;

    /// <summary>Every ball set.</summary>
    public static IReadOnlyList<BallSet> All => Sets.All;

    /// <summary>
    /// The standard model's parameters for this set's balls and their cloth (physics-standard-model.md,
    /// "Against the real table"): pool's set on <see cref="Physics.PhysicsParams.Pool"/>, any other on
    /// the snooker cloth as measured, <see cref="Physics.PhysicsParams.Snooker"/>, with its own radius and
    /// mass; a set with a cloth of its own (carom's heated cloth) on that cloth.
    /// </summary>
    public Physics.PhysicsParams DefaultParams => Cloth is { } cloth ? cloth.On(BallParams) : BallParams;

    /// <summary>The cloth the set is played on by default, or null for the model's defaults (carom's heated cloth).</summary>
    public Physics.Cloth? Cloth { get; init; }

    // Pool's balls on pool's values; a set on a cloth of its own (carom's) keeps pool's ball-ball
    // and cushion laws and spin-down rate with its own radius and mass; any other is snooker's.
    private Physics.PhysicsParams BallParams =>
        Radius == Physics.PhysicsParams.DefaultRadius && Mass == Physics.PhysicsParams.DefaultMass
            ? Physics.PhysicsParams.Pool
            : Cloth is not null
                ? Physics.PhysicsParams.Pool with
                {
                    R = Radius,
                    M = Mass,
                    MuSp = Physics.PhysicsParams.SpinDecelerationToMuSp(Physics.PhysicsParams.Pool.SpinDeceleration, Radius, Physics.PhysicsParams.Pool.G),
                    CueEndMass = Mass / 21,
                }
                : Physics.PhysicsParams.Snooker(Radius, Mass);

    /// <summary>The name of a ball of any set ("cue", "7", "red-3", "pink"), or its number when no set has it.</summary>
    public static string NameOfAny(BallId id)
    {
        foreach (var set in All)
        {
            if (set.Contains(id))
            {
                return set.NameOf(id);
            }
        }
        return id.Value.ToString(CultureInfo.InvariantCulture);
    }

    /// <summary>Parses the name of a ball of any set.</summary>
    public static bool TryParseAny(string? text, out BallId id)
    {
        foreach (var set in All)
        {
            if (set.TryParse(text, out id))
            {
                return true;
            }
        }
        id = default;
        return false;
    }

    /// <summary>The ball <paramref name="id"/> of whichever set has it.</summary>
    /// <exception cref="ArgumentException">When no set has it.</exception>
    public static BallKind KindOfAny(BallId id) =>
        All.FirstOrDefault(s => s.Contains(id))?.Kind(id) ?? throw new ArgumentException($"ball {id.Value} is in no ball set", nameof(id));

    /// <summary>Snooker's ball of the colour <paramref name="colour"/> ("yellow" .. "black").</summary>
    public static BallId Colour(string colour)
    {
        int i = Array.IndexOf(Sets.ColourNames, colour);
        return i >= 0 ? new BallId(FirstRed + Reds + i) : throw new ArgumentException($"\"{colour}\" is not a colour of snooker", nameof(colour));
    }

    private static BallSet CreateSnooker()
    {
        (float R, float G, float B)[] colours =
        [
            (0.97f, 0.84f, 0.10f), (0.05f, 0.45f, 0.20f), (0.42f, 0.23f, 0.10f), // yellow, green, brown
            (0.07f, 0.25f, 0.78f), (0.96f, 0.50f, 0.62f), (0.04f, 0.04f, 0.045f), // blue, pink, black
        ];
        var cue = new BallId(0);
        var balls = new List<BallKind> { new(cue, "cue", 0, new BallLook(0.96f, 0.95f, 0.90f, false, false)) };
        for (int k = 1; k <= Reds; k++)
        {
            balls.Add(new BallKind(new BallId(FirstRed + k - 1), "red-" + k.ToString(CultureInfo.InvariantCulture), 1, new BallLook(0.78f, 0.05f, 0.06f, false, false)));
        }
        for (int i = 0; i < Colours.Count; i++)
        {
            var (r, g, b) = colours[i];
            balls.Add(new BallKind(new BallId(FirstRed + Reds + i), Colours[i], i + 2, new BallLook(r, g, b, false, false)));
        }
        var groups = new Dictionary<string, IReadOnlyList<BallId>>
        {
            ["reds"] = [.. balls.Skip(1).Take(Reds).Select(b => b.Id)],
            ["colours"] = [.. balls.Skip(1 + Reds).Select(b => b.Id)],
        };
        return new BallSet("snooker", balls, [cue], groups, Table.SnookerTable.BallDiameter / 2, SnookerMass);
    }

    /// <summary>Mass of a snooker ball (kg).</summary>
    public const double SnookerMass = 0.142;

    // Made on first use, after Pool (the order of static fields across a partial class's files is not fixed).
    private static class Sets
    {
        public static readonly string[] ColourNames = ["yellow", "green", "brown", "blue", "pink", "black"];
        public static readonly BallSet Snooker = CreateSnooker();
        public static readonly BallSet Carom = CreateCarom();
        public static readonly BallSet[] All = [Pool, Snooker, Carom];
    }
}
