using System.Collections;
using System.Runtime.CompilerServices;
using Billiards.Core.Mathematics;

namespace Billiards.Core.Balls;

/// <summary>
/// Where the balls on the table stand (centres, m; z = R at rest), as one immutable value: the
/// game between shots (<see cref="Rules.Match.Balls"/>), each shot's record
/// (<see cref="Rules.MatchShot.After"/>), a take-back's snapshot, the planner's position, a rack and
/// a scene's start. A ball appears once; the order is kept, and it is the order a simulation made
/// from the layout gives its balls, so the same layout always gives the same simulation.
/// </summary>
/// <remarks>
/// Changes make a new layout and leave this one as it was (a snapshot stays a snapshot). Two
/// layouts are equal when they hold the same balls at the same positions in the same order.
/// </remarks>
[CollectionBuilder(typeof(BallLayout), nameof(Create))]
public sealed class BallLayout : IReadOnlyList<(BallId Id, Vec3 Position)>, IEquatable<BallLayout>
{
    private readonly BallId[] _ids;
    private readonly Vec3[] _positions;

    /// <summary>A layout of the given balls, in their order.</summary>
    /// <exception cref="ArgumentException">A ball appears twice.</exception>
    public BallLayout(IEnumerable<(BallId Id, Vec3 Position)> balls)
    {
        ArgumentNullException.ThrowIfNull(balls);
        var list = balls as IReadOnlyCollection<(BallId Id, Vec3 Position)> ?? [.. balls];
        _ids = new BallId[list.Count];
        _positions = new Vec3[list.Count];
        int i = 0;
        foreach (var (id, position) in list)
        {
            if (Array.IndexOf(_ids, id, 0, i) >= 0)
            {
                throw new ArgumentException($"ball {id} appears twice in a layout", nameof(balls));
            }
            _ids[i] = id;
            _positions[i++] = position;
        }
    }

    private BallLayout(BallId[] ids, Vec3[] positions)
    {
        _ids = ids;
        _positions = positions;
    }

    /// <summary>A layout of the given balls, in their order (a collection expression's builder).</summary>
    /// <exception cref="ArgumentException">A ball appears twice.</exception>
    public static BallLayout Create(ReadOnlySpan<(BallId Id, Vec3 Position)> balls) => new(balls.ToArray());

    /// <summary>No balls.</summary>
    public static BallLayout Empty { get; } = new([], []);

    /// <summary>
    /// The balls of <paramref name="balls"/> in play (pocketed and lost ones left out), each with
    /// its id from <paramref name="ids"/> (index-aligned), in their order; with <paramref name="z"/>,
    /// every centre at that height (on the bed, for balls at rest). A simulation's balls and a
    /// shot record's, before or after the shot, all become layouts here.
    /// </summary>
    public static BallLayout InPlay(ReadOnlySpan<BallState> balls, IReadOnlyList<BallId> ids, double? z = null)
    {
        ArgumentNullException.ThrowIfNull(ids);
        var list = new List<(BallId, Vec3)>(balls.Length);
        for (int i = 0; i < balls.Length; i++)
        {
            if (!balls[i].IsOutOfPlay)
            {
                list.Add((ids[i], z is { } h ? balls[i].Position with { Z = h } : balls[i].Position));
            }
        }
        return new BallLayout(list);
    }

    /// <summary>Number of balls.</summary>
    public int Count => _ids.Length;

    /// <summary>Ball ids, index-aligned with <see cref="Positions"/>.</summary>
    public IReadOnlyList<BallId> Ids => _ids;

    /// <summary>Ball centres (m), index-aligned with <see cref="Ids"/>.</summary>
    public IReadOnlyList<Vec3> Positions => _positions;

    internal ReadOnlySpan<BallId> IdSpan => _ids;

    internal ReadOnlySpan<Vec3> PositionSpan => _positions;

    /// <summary>The <paramref name="index"/>-th ball and its centre.</summary>
    public (BallId Id, Vec3 Position) this[int index] => (_ids[index], _positions[index]);

    /// <summary>The centre of <paramref name="id"/>.</summary>
    /// <exception cref="KeyNotFoundException">The ball is not on the table.</exception>
    public Vec3 this[BallId id] => IndexOf(id) is var i and >= 0 ? _positions[i] : throw new KeyNotFoundException($"ball {id} is not on the table");

    /// <summary>Index of <paramref name="id"/>, or -1 when it is not on the table.</summary>
    public int IndexOf(BallId id) => Array.IndexOf(_ids, id);

    /// <summary>True when <paramref name="id"/> is on the table.</summary>
    public bool Contains(BallId id) => IndexOf(id) >= 0;

    /// <summary>The centre of <paramref name="id"/>, or null when it is not on the table.</summary>
    public Vec3? PositionOf(BallId id) => IndexOf(id) is var i and >= 0 ? _positions[i] : null;

    /// <summary>This layout with <paramref name="id"/> at <paramref name="position"/>: moved where it stands in the order, or added last.</summary>
    public BallLayout With(BallId id, Vec3 position)
    {
        int i = IndexOf(id);
        if (i >= 0)
        {
            var positions = (Vec3[])_positions.Clone();
            positions[i] = position;
            return new BallLayout(_ids, positions);
        }
        return new BallLayout([.. _ids, id], [.. _positions, position]);
    }

    /// <summary>This layout without <paramref name="id"/> (itself when the ball is not on the table).</summary>
    public BallLayout Without(BallId id)
    {
        int i = IndexOf(id);
        return i < 0 ? this : new BallLayout([.. _ids[..i], .. _ids[(i + 1)..]], [.. _positions[..i], .. _positions[(i + 1)..]]);
    }

    /// <summary>
    /// This layout in the order of <paramref name="order"/> (a ball set's ids): the balls it names
    /// first, in its order, then any others in their order here (itself when already so).
    /// </summary>
    public BallLayout OrderedBy(IReadOnlyList<BallId> order)
    {
        ArgumentNullException.ThrowIfNull(order);
        var keys = new int[_ids.Length];
        bool sorted = true;
        for (int i = 0; i < keys.Length; i++)
        {
            int k = IndexIn(order, _ids[i]);
            keys[i] = k;
            sorted &= i == 0 || keys[i - 1] <= k;
        }
        if (sorted)
        {
            return this;
        }
        var index = Enumerable.Range(0, keys.Length).OrderBy(i => keys[i]).ToArray();
        return new BallLayout([.. index.Select(i => _ids[i])], [.. index.Select(i => _positions[i])]);
    }

    private static int IndexIn(IReadOnlyList<BallId> order, BallId id)
    {
        for (int i = 0; i < order.Count; i++)
        {
            if (order[i] == id)
            {
                return i;
            }
        }
        return int.MaxValue;
    }

    /// <inheritdoc />
    public IEnumerator<(BallId Id, Vec3 Position)> GetEnumerator()
    {
        for (int i = 0; i < _ids.Length; i++)
        {
            yield return (_ids[i], _positions[i]);
        }
    }

    IEnumerator IEnumerable.GetEnumerator() => GetEnumerator();

    /// <inheritdoc />
    public bool Equals(BallLayout? other) =>
        other is not null && (ReferenceEquals(this, other) || (_ids.AsSpan().SequenceEqual(other._ids) && _positions.AsSpan().SequenceEqual(other._positions)));

    /// <inheritdoc />
    public override bool Equals(object? obj) => Equals(obj as BallLayout);

    /// <inheritdoc />
    public override int GetHashCode()
    {
        var hash = new HashCode();
        for (int i = 0; i < _ids.Length; i++)
        {
            hash.Add(_ids[i]);
            hash.Add(_positions[i]);
        }
        return hash.ToHashCode();
    }

    /// <inheritdoc />
    public override string ToString() => string.Join(", ", this.Select(b => $"{b.Id} {b.Position}"));
}
