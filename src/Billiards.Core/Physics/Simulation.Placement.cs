using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Setup;

namespace Billiards.Core.Physics;

/// <summary>A placement that the table does not allow; the message names the ball and the problem.</summary>
public sealed class PlacementException : ArgumentException
{
    /// <summary>Creates the exception with the problem as its message.</summary>
    public PlacementException(string problem)
        : base(problem)
    {
    }
}

// Placing, spotting, removing and reracking balls between shots (ball in hand, rules.md's spot
// rule, reracks). Every placement is tested by Setup.Placement, the scene loader's test.
public abstract partial class Simulation
{
    /// <summary>Radius of the model's balls (m).</summary>
    public abstract double BallRadius { get; }

    /// <summary>
    /// What is wrong with placing ball <paramref name="id"/> at rest at <paramref name="position"/>
    /// (m; z is ignored) in <paramref name="region"/>, against the table and every other ball in
    /// play; null when the placement is allowed. The ball itself may be in play or out of it.
    /// </summary>
    public string? PlacementProblem(BallId id, Vec3 position, PlacementRegion region = PlacementRegion.Table)
    {
        int index = IndexOf(id);
        if (index < 0)
        {
            return $"ball \"{id}\" is not in this game's ball set";
        }
        if (Placement.OnTable(Table, BallRadius, id, position, region) is { } problem)
        {
            return problem;
        }
        var balls = Balls;
        for (int j = 0; j < balls.Length; j++)
        {
            if (j != index && !balls[j].IsOutOfPlay
                && Placement.Overlap(BallRadius, id, position, Ids[j], balls[j].Position) is { } overlap)
            {
                return overlap;
            }
        }
        return null;
    }

    /// <summary>
    /// Puts ball <paramref name="id"/> at rest at <paramref name="position"/> (m; z becomes R), in
    /// play, when <see cref="PlacementProblem"/> allows it: ball in hand, or any ball moved by a
    /// tool. Only between shots.
    /// </summary>
    /// <exception cref="PlacementException">When the placement is not allowed (the message says why).</exception>
    /// <exception cref="InvalidOperationException">While balls move.</exception>
    public void PlaceBall(BallId id, Vec3 position, PlacementRegion region = PlacementRegion.Table)
    {
        RequireRest();
        if (PlacementProblem(id, position, region) is { } problem)
        {
            throw new PlacementException(problem);
        }
        PutBall(IndexOf(id), position with { Z = BallRadius });
    }

    /// <summary>As <see cref="PlaceBall"/>, but reports a refused placement instead of throwing.</summary>
    /// <returns>True when the ball was placed; else <paramref name="problem"/> says why not.</returns>
    /// <exception cref="InvalidOperationException">While balls move.</exception>
    public bool TryPlaceBall(BallId id, Vec3 position, PlacementRegion region, out string? problem)
    {
        RequireRest();
        problem = PlacementProblem(id, position, region);
        if (problem is not null)
        {
            return false;
        }
        PutBall(IndexOf(id), position with { Z = BallRadius });
        return true;
    }

    /// <summary>
    /// Takes ball <paramref name="id"/> out of play without a pocket: it reports
    /// <see cref="MotionState.Pocketed"/> with pocket -1 and takes part in nothing until placed
    /// again. Only between shots.
    /// </summary>
    /// <exception cref="PlacementException">When the ball is not in this simulation.</exception>
    /// <exception cref="InvalidOperationException">While balls move.</exception>
    public void RemoveBall(BallId id)
    {
        RequireRest();
        int index = IndexOf(id);
        if (index < 0)
        {
            throw new PlacementException($"ball \"{id}\" is not in this game's ball set");
        }
        TakeOut(index);
    }

    /// <summary>
    /// The balls in play (pocketed and lost ones left out) as a layout, in the simulation's order;
    /// with <paramref name="z"/>, every centre at that height (on the bed, for balls at rest).
    /// </summary>
    public BallLayout InPlay(double? z = null) => BallLayout.InPlay(Balls, Ids, z);

    /// <summary>
    /// Puts several balls at rest at once (a rerack, a set position): every ball listed is tested
    /// against the table, against the others listed and against the balls in play that are not
    /// listed; nothing moves unless all may be placed. Only between shots.
    /// </summary>
    /// <exception cref="PlacementException">When a ball is unknown, listed twice, or may not stand where listed.</exception>
    /// <exception cref="InvalidOperationException">While balls move.</exception>
    public void PlaceBalls(IReadOnlyList<(BallId Id, Vec3 Position)> balls)
    {
        ArgumentNullException.ThrowIfNull(balls);
        RequireRest();
        var indices = new int[balls.Count];
        var listed = new bool[Ids.Count];
        for (int k = 0; k < balls.Count; k++)
        {
            int index = IndexOf(balls[k].Id);
            if (index < 0)
            {
                throw new PlacementException($"ball \"{balls[k].Id}\" is not in this game's ball set");
            }
            if (listed[index])
            {
                throw new PlacementException($"ball \"{balls[k].Id}\" is listed twice");
            }
            listed[index] = true;
            indices[k] = index;
        }
        var all = new List<(BallId Id, Vec3 Position)>(balls);
        var current = Balls;
        for (int j = 0; j < current.Length; j++)
        {
            if (!listed[j] && !current[j].IsOutOfPlay)
            {
                all.Add((Ids[j], current[j].Position));
            }
        }
        if (Placement.Check(Table, BallRadius, all, out _) is { } problem)
        {
            throw new PlacementException(problem);
        }
        for (int k = 0; k < balls.Count; k++)
        {
            PutBall(indices[k], balls[k].Position with { Z = BallRadius });
        }
    }

    /// <summary>
    /// Reracks: the balls of <paramref name="rack"/> that this simulation has go back to where
    /// <see cref="Initializer.Rack"/> puts them (its seed's jitter included); the other balls stay.
    /// Only between shots.
    /// </summary>
    /// <exception cref="PlacementException">When a ball left on the table is in the rack's way.</exception>
    /// <exception cref="InvalidOperationException">While balls move.</exception>
    public void Rerack(RackSpec rack)
    {
        ArgumentNullException.ThrowIfNull(rack);
        var placed = new List<(BallId Id, Vec3 Position)>();
        foreach (var (id, position) in Initializer.Rack(rack, Table, BallRadius))
        {
            if (IndexOf(id) >= 0)
            {
                placed.Add((id, position));
            }
        }
        PlaceBalls(placed);
    }

    /// <summary>
    /// Reracks the given balls in the shape of <paramref name="shape"/>, filling its spots in order
    /// (apex first, rows from the foot spot towards the foot rail, each row from -y to +y) without
    /// jitter; with <paramref name="apexEmpty"/> the apex spot is left free (14.1's rerack of 14).
    /// Only between shots.
    /// </summary>
    /// <exception cref="PlacementException">When there are more balls than spots, or a ball left on the table is in the way.</exception>
    /// <exception cref="InvalidOperationException">While balls move.</exception>
    public void Rerack(IReadOnlyList<BallId> balls, RackGame shape, bool apexEmpty = false)
    {
        ArgumentNullException.ThrowIfNull(balls);
        var spots = Initializer.RackSpots(shape, Table, BallRadius);
        int first = apexEmpty ? 1 : 0;
        if (balls.Count > spots.Count - first)
        {
            throw new PlacementException($"{balls.Count} balls do not fit the rack's {spots.Count - first} spots");
        }
        var placed = new List<(BallId Id, Vec3 Position)>(balls.Count);
        for (int k = 0; k < balls.Count; k++)
        {
            placed.Add((balls[k], spots[first + k]));
        }
        PlaceBalls(placed);
    }

    /// <summary>The model puts the ball at <paramref name="index"/> at rest at <paramref name="position"/> (m, z = R), in play; the rest of the model's state follows.</summary>
    protected abstract void PutBall(int index, Vec3 position);

    /// <summary>The model takes the ball at <paramref name="index"/> out of play (no pocket).</summary>
    protected abstract void TakeOut(int index);

    private void RequireRest()
    {
        if (!IsAtRest)
        {
            throw new InvalidOperationException("balls can only be placed while every ball rests");
        }
    }
}
