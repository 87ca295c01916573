using System.Globalization;

namespace Billiards.Core.Balls;

/// <summary>How a ball looks: its base colour (sRGB, each 0..1), whether it is striped, whether it carries its number.</summary>
/// <param name="Red">Red, 0..1 (sRGB).</param>
/// <param name="Green">Green, 0..1 (sRGB).</param>
/// <param name="Blue">Blue, 0..1 (sRGB).</param>
/// <param name="Striped">A white ball with a band of the colour (pool's 9-15), else solid.</param>
/// <param name="Numbered">The ball shows its name in a white disc (pool's object balls).</param>
public sealed record BallLook(float Red, float Green, float Blue, bool Striped, bool Numbered);

/// <summary>One ball of a set.</summary>
/// <param name="Id">Its identity.</param>
/// <param name="Name">Its name in scene and result files ("cue", "1" .. "15").</param>
/// <param name="Value">What it is worth: pool's number (snooker's points would go here).</param>
/// <param name="Look">How it is drawn.</param>
public sealed record BallKind(BallId Id, string Name, int Value, BallLook Look);

/// <summary>
/// The balls a kind of billiards is played with, as data: each ball's id, name, value and look,
/// which of them are cue balls, the named groups, and the balls' radius and mass: pool's set and
/// snooker's (<see cref="Snooker"/>) and carom's, with its two cue balls (<see cref="Carom"/>). The code that
/// needs to know which ball is a cue ball or how many balls there are asks the set. Ids are unique
/// across the sets (a set's cue ball excepted, "cue" in each), so an id names its ball in files
/// whatever the set (<see cref="NameOfAny"/>).
/// </summary>
public sealed partial class BallSet
{
    private readonly BallKind[] _kinds;
    private readonly Dictionary<string, BallKind> _byName;
    private readonly Dictionary<string, IReadOnlyList<BallId>> _groups;
    private readonly HashSet<BallId> _cueBalls;
    private readonly bool[] _isCue;

    /// <summary>Creates a set.</summary>
    /// <param name="name">The set's name.</param>
    /// <param name="balls">Every ball, in the set's order (cue balls first).</param>
    /// <param name="cueBalls">The balls a player strikes.</param>
    /// <param name="groups">Named groups of object balls (8-ball's "solids" and "stripes").</param>
    /// <param name="radius">Ball radius (m).</param>
    /// <param name="mass">Ball mass (kg).</param>
    public BallSet(string name, IReadOnlyList<BallKind> balls, IReadOnlyList<BallId> cueBalls, IReadOnlyDictionary<string, IReadOnlyList<BallId>> groups, double radius, double mass)
    {
        ArgumentNullException.ThrowIfNull(balls);
        ArgumentNullException.ThrowIfNull(cueBalls);
        ArgumentNullException.ThrowIfNull(groups);
        Name = name;
        _kinds = [.. balls];
        _byName = _kinds.ToDictionary(b => b.Name, StringComparer.Ordinal);
        _groups = groups.ToDictionary(g => g.Key, g => g.Value, StringComparer.Ordinal);
        _cueBalls = [.. cueBalls];
        // Indexed by id: asked for every ball in the planner's inner loops.
        _isCue = new bool[_kinds.Length == 0 ? 0 : _kinds.Max(b => b.Id.Value) + 1];
        foreach (var id in cueBalls)
        {
            if (id.Value >= 0 && id.Value < _isCue.Length)
            {
                _isCue[id.Value] = true;
            }
        }
        CueBalls = [.. cueBalls];
        Ids = [.. _kinds.Select(b => b.Id)];
        Radius = radius;
        Mass = mass;
        HighestNumber = _kinds.Where(b => !_cueBalls.Contains(b.Id)).Select(b => b.Value).DefaultIfEmpty(0).Max();
    }

    /// <summary>
    /// Pool: the cue ball ("cue", white) and the object balls 1 .. 15 in the usual colours, 1-7
    /// solids, 8 black, 9-15 striped; the solids and stripes groups; R = 28.575 mm, m = 0.170097 kg (the physics' defaults).
    /// </summary>
    public static BallSet Pool { get; } = CreatePool();

    /// <summary>The set's name.</summary>
    public string Name { get; }

    /// <summary>Every ball of the set, in the set's order (cue balls first).</summary>
    public IReadOnlyList<BallId> Ids { get; }

    /// <summary>Every ball with its name, value and look, in the set's order.</summary>
    public IReadOnlyList<BallKind> Balls => _kinds;

    /// <summary>The cue balls: the balls a player strikes.</summary>
    public IReadOnlyList<BallId> CueBalls { get; }

    /// <summary>Number of balls, the cue balls included.</summary>
    public int Count => _kinds.Length;

    /// <summary>The balls' radius (m).</summary>
    public double Radius { get; }

    /// <summary>The balls' mass (kg).</summary>
    public double Mass { get; }

    /// <summary>The highest object-ball value of the set (pool: 15).</summary>
    public int HighestNumber { get; }

    /// <summary>True for a cue ball of the set.</summary>
    public bool IsCueBall(BallId id) => (uint)id.Value < (uint)_isCue.Length && _isCue[id.Value];

    /// <summary>The balls of a named group, or none.</summary>
    public IReadOnlyList<BallId> Group(string name) => _groups.TryGetValue(name, out var balls) ? balls : [];

    /// <summary>The ball <paramref name="id"/> of the set.</summary>
    /// <exception cref="ArgumentException">When the set has no such ball.</exception>
    public BallKind Kind(BallId id) => Contains(id) && _kinds[IndexOf(id)] is var kind
        ? kind
        : throw new ArgumentException($"ball {id.Value} is not in the {Name} set", nameof(id));

    /// <summary>The index of a ball in the set's order, or -1.</summary>
    public int IndexOf(BallId id)
    {
        for (int i = 0; i < _kinds.Length; i++)
        {
            if (_kinds[i].Id == id)
            {
                return i;
            }
        }
        return -1;
    }

    /// <summary>How the set's ids are written, for messages: "cue" or "1" .. "15".</summary>
    public string Describe() => _kinds.Length <= 3
        ? string.Join(", ", _kinds.Select(b => $"\"{b.Name}\""))
        : $"\"{_kinds[0].Name}\" or \"{_kinds[1].Name}\" .. \"{_kinds[^1].Name}\"";

    /// <summary>True when <paramref name="id"/> is a ball of the set.</summary>
    public bool Contains(BallId id) => IndexOf(id) >= 0;

    /// <summary>Parses a ball's name in the set ("cue", or a number written without leading zeros).</summary>
    public bool TryParse(string? text, out BallId id)
    {
        if (text is not null && _byName.TryGetValue(text, out var kind))
        {
            id = kind.Id;
            return true;
        }
        id = default;
        return false;
    }

    /// <summary>The ball's name in files ("cue", "1" ..), or its number when the set has no such ball.</summary>
    public string NameOf(BallId id)
    {
        int i = IndexOf(id);
        return i >= 0 ? _kinds[i].Name : id.Value.ToString(CultureInfo.InvariantCulture);
    }

    private const int PoolObjectBalls = 15, PoolEight = 8;

    private static BallSet CreatePool()
    {
        // Pool's colours by number mod 8 (a local: Pool is made before any other static field).
        (float R, float G, float B)[] colours =
        [
            (0.98f, 0.80f, 0.06f), (0.06f, 0.22f, 0.72f), (0.86f, 0.09f, 0.07f), (0.36f, 0.13f, 0.58f), // yellow, blue, red, purple
            (0.98f, 0.45f, 0.06f), (0.04f, 0.48f, 0.23f), (0.50f, 0.10f, 0.08f), (0.04f, 0.04f, 0.045f), // orange, green, maroon, black
        ];
        var cue = new BallId(0);
        var balls = new List<BallKind> { new(cue, "cue", 0, new BallLook(0.96f, 0.95f, 0.90f, false, false)) };
        for (int n = 1; n <= PoolObjectBalls; n++)
        {
            var (r, g, b) = colours[(n - 1) % PoolEight];
            balls.Add(new BallKind(new BallId(n), n.ToString(CultureInfo.InvariantCulture), n, new BallLook(r, g, b, n > PoolEight, true)));
        }
        var groups = new Dictionary<string, IReadOnlyList<BallId>>
        {
            ["solids"] = [.. Enumerable.Range(1, PoolEight - 1).Select(n => new BallId(n))],
            ["stripes"] = [.. Enumerable.Range(PoolEight + 1, PoolObjectBalls - PoolEight).Select(n => new BallId(n))],
        };
        return new BallSet("pool", balls, [cue], groups, Physics.PhysicsParams.DefaultRadius, Physics.PhysicsParams.DefaultMass);
    }
}
