using Billiards.Core.Mathematics;

namespace Billiards.Core.Table;

/// <summary>
/// One pocket of a table, as data: its name, where it is on the outline of the playing area, and
/// the shape of its mouth. Positions are in half-lengths and half-widths, so that a table's
/// <c>length</c> and <c>width</c> overrides move its pockets with the rails.
/// </summary>
/// <param name="Name">The pocket's name in scene and result files ("head-left", ..., scene-format.md).</param>
/// <param name="End">Along the length: -1 at the head rail (x = -L/2), 0 in the middle of a long rail, +1 at the foot rail.</param>
/// <param name="Side">Across: +1 on the left (y = +W/2), -1 on the right, as seen from the head rail.</param>
/// <param name="Mouth">The mouth, jaw tip to jaw tip (m); a corner's is measured across the diagonal.</param>
/// <param name="JawAngleDeg">Angle between each jaw and the rail it leaves, measured through the cushion (deg; WPA 142 corner, 104 side).</param>
public sealed record PocketSpec(string Name, int End, int Side, double Mouth, double JawAngleDeg)
{
    /// <summary>True for a corner pocket (at the head or foot rail), false for a pocket in a long rail.</summary>
    public bool IsCorner => End != 0;

    /// <summary>How far each rail it cuts stops short of the pocket's corner or middle point (m): mouth / sqrt 2 at a corner, mouth / 2 in a long rail.</summary>
    public double RailCut => IsCorner ? Mouth / Math.Sqrt(2) : Mouth / 2;

    /// <summary>The unit direction out of the table through the mouth (bed plane).</summary>
    public Vec3 Outward => IsCorner ? new Vec3(End, Side, 0).Normalized() : new Vec3(0, Side, 0);

    /// <summary>The middle of the mouth line on <paramref name="table"/> (m, z = 0).</summary>
    public Vec3 MouthMiddle(TableSpec table)
    {
        ArgumentNullException.ThrowIfNull(table);
        if (!IsCorner)
        {
            return new Vec3(0, Side * table.HalfWidth, 0);
        }
        double c = RailCut;
        return new Vec3(End * (table.HalfLength - c / 2), Side * (table.HalfWidth - c / 2), 0);
    }
}

/// <summary>
/// The pockets of a table, in index order (the index is <see cref="PocketId.Index"/> and what a
/// ball's <see cref="Balls.BallState.Pocket"/> holds). Pockets sit at the corners and in the middle
/// of the long rails, each at most once; a table may have any of them. Two sets are equal when
/// their pockets are.
/// </summary>
public sealed class PocketSet : IReadOnlyList<PocketSpec>, IEquatable<PocketSet>
{
    private readonly PocketSpec[] _pockets;
    private readonly PocketId[] _ids;

    /// <summary>Creates a set from its pockets, in index order.</summary>
    /// <exception cref="ArgumentException">For two pockets of one name or one place, or a place off the outline.</exception>
    public PocketSet(IEnumerable<PocketSpec> pockets)
    {
        ArgumentNullException.ThrowIfNull(pockets);
        _pockets = [.. pockets];
        for (int i = 0; i < _pockets.Length; i++)
        {
            var p = _pockets[i];
            if (p.End is < -1 or > 1 || p.Side is not (-1 or 1))
            {
                throw new ArgumentException($"pocket \"{p.Name}\" is not at a corner or the middle of a long rail (end {p.End}, side {p.Side})", nameof(pockets));
            }
            for (int j = 0; j < i; j++)
            {
                if (_pockets[j].Name == p.Name || (_pockets[j].End == p.End && _pockets[j].Side == p.Side))
                {
                    throw new ArgumentException($"pockets \"{_pockets[j].Name}\" and \"{p.Name}\" share a name or a place", nameof(pockets));
                }
            }
        }
        _ids = [.. _pockets.Select((p, i) => new PocketId(i, p.Name))];
    }

    /// <summary>No pockets: a carom table.</summary>
    public static PocketSet None { get; } = new([]);

    /// <summary>
    /// The six pockets of a pool or snooker table, in index order head-left, head-right,
    /// side-left, side-right, foot-left, foot-right (scene-format.md's names: left and right as
    /// seen from the head rail).
    /// </summary>
    /// <param name="cornerMouth">Corner mouth, jaw tip to jaw tip (m).</param>
    /// <param name="sideMouth">Side mouth, jaw tip to jaw tip (m).</param>
    /// <param name="cornerJawDeg">Corner jaw angle (deg).</param>
    /// <param name="sideJawDeg">Side jaw angle (deg).</param>
    public static PocketSet Six(double cornerMouth, double sideMouth, double cornerJawDeg, double sideJawDeg) => new(
    [
        new("head-left", -1, 1, cornerMouth, cornerJawDeg),
        new("head-right", -1, -1, cornerMouth, cornerJawDeg),
        new("side-left", 0, 1, sideMouth, sideJawDeg),
        new("side-right", 0, -1, sideMouth, sideJawDeg),
        new("foot-left", 1, 1, cornerMouth, cornerJawDeg),
        new("foot-right", 1, -1, cornerMouth, cornerJawDeg),
    ]);

    /// <summary>Number of pockets.</summary>
    public int Count => _pockets.Length;

    /// <summary>The pocket of index <paramref name="index"/>.</summary>
    public PocketSpec this[int index] => _pockets[index];

    /// <summary>The pocket of <paramref name="pocket"/>.</summary>
    public PocketSpec this[PocketId pocket] => _pockets[pocket.Index];

    /// <summary>Every pocket's identity, in index order.</summary>
    public IReadOnlyList<PocketId> Ids => _ids;

    /// <summary>The identity of the pocket of index <paramref name="index"/>, or <see cref="PocketId.None"/> for any other index (-1: in play).</summary>
    public PocketId Id(int index) => (uint)index < (uint)_ids.Length ? _ids[index] : PocketId.None;

    /// <summary>The name of the pocket of index <paramref name="index"/>, or "?" for an unknown index.</summary>
    public string NameOf(int index) => (uint)index < (uint)_pockets.Length ? _pockets[index].Name : "?";

    /// <summary>The pocket at a place of the outline, or null when the table has none there.</summary>
    public PocketSpec? At(int end, int side) => Array.Find(_pockets, p => p.End == end && p.Side == side);

    /// <summary>The index of the pocket at a place of the outline, or -1.</summary>
    public int IndexAt(int end, int side) => Array.FindIndex(_pockets, p => p.End == end && p.Side == side);

    /// <summary>Parses a pocket's name (not "none").</summary>
    public bool TryParse(string? name, out PocketId pocket)
    {
        int i = Array.FindIndex(_pockets, p => p.Name == name);
        pocket = Id(i);
        return i >= 0;
    }

    /// <summary>The names, quoted and comma-separated, for messages.</summary>
    public string Describe() => string.Join(", ", _pockets.Select(p => $"\"{p.Name}\""));

    /// <inheritdoc/>
    public IEnumerator<PocketSpec> GetEnumerator() => ((IEnumerable<PocketSpec>)_pockets).GetEnumerator();

    System.Collections.IEnumerator System.Collections.IEnumerable.GetEnumerator() => GetEnumerator();

    /// <inheritdoc/>
    public bool Equals(PocketSet? other) => other is not null && _pockets.SequenceEqual(other._pockets);

    /// <inheritdoc/>
    public override bool Equals(object? obj) => Equals(obj as PocketSet);

    /// <inheritdoc/>
    public override int GetHashCode()
    {
        var hash = new HashCode();
        foreach (var p in _pockets)
        {
            hash.Add(p);
        }
        return hash.ToHashCode();
    }

    /// <summary>The pockets by name and place, for messages and cache keys.</summary>
    public override string ToString() =>
        string.Join(";", _pockets.Select(p => FormattableString.Invariant($"{p.Name}@{p.End},{p.Side}:{p.Mouth:R}/{p.JawAngleDeg:R}")));
}
