using Billiards.Core.Balls;

namespace Billiards.Core.Physics;

/// <summary>
/// A simulation's whole dynamic state, owned by the caller: the balls, the clock and step count,
/// the events so far, and the model's own state (the standard engine's predictions, queue, grid,
/// pair cache and contact memory; the thesis engine's effet and random state). Made once by
/// <see cref="Simulation.CreateSnapshot"/>; after that <see cref="Simulation.Capture"/> and
/// <see cref="Simulation.Restore"/> copy into and out of it without allocating, and a simulation
/// restored from it continues bit for bit as the one it was taken from would have.
/// </summary>
/// <remarks>
/// A snapshot restores into the simulation it came from or any other made from the same
/// <see cref="Physics.TableModel"/> with the same balls. Restoring only reads the snapshot, so
/// several simulations on several threads may restore from one snapshot at once.
/// </remarks>
public abstract class SimulationSnapshot
{
    private readonly IReadOnlyList<BallId> _ids;

    /// <summary>Creates the common part of a snapshot of <paramref name="simulation"/> (nothing captured yet).</summary>
    protected SimulationSnapshot(Simulation simulation)
    {
        TableModel = simulation.TableModel;
        _ids = simulation.Ids;
    }

    /// <summary>The table model of the simulations this snapshot fits.</summary>
    public TableModel TableModel { get; }

    /// <summary>Simulated time when the state was captured (s).</summary>
    public double Time { get; internal set; }

    /// <summary>Step count when the state was captured.</summary>
    public long StepCount { get; internal set; }

    internal int EventCapHits { get; set; }

    internal int TruncatedImpacts { get; set; }

    internal EventLog Events { get; } = new();

    /// <summary>True when this snapshot can be captured from or restored into <paramref name="simulation"/>.</summary>
    public bool Fits(Simulation simulation)
    {
        if (!ReferenceEquals(TableModel, simulation.TableModel) || _ids.Count != simulation.Ids.Count)
        {
            return false;
        }
        for (int i = 0; i < _ids.Count; i++)
        {
            if (_ids[i] != simulation.Ids[i])
            {
                return false;
            }
        }
        return true;
    }
}
