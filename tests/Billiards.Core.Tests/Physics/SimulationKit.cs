using Billiards.Core.Physics.Standard;
using Billiards.Core.Physics.Thesis;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.Core.Tests.Physics;

/// <summary>Breaks under every model and integrator, and bitwise comparison of simulation states.</summary>
internal static class SimulationKit
{
    /// <summary>Scene file, model and integrator of each break the tests run.</summary>
    public static TheoryData<string, string, string> Breaks => new()
    {
        { "thesis-eight-ball-break.json", ThesisModel.ModelName, Integrators.Fixed },
        { "eight-ball-break.json", StandardModel.ModelName, Integrators.Exact },
        { "eight-ball-break.json", StandardModel.ModelName, Integrators.Event },
        { "eight-ball-break.json", StandardModel.ModelName, Integrators.Euler },
    };

    public static Scene Load(string file, string model, string integrator) =>
        SceneLoader.Load(AssetFolder.Scene(file), new SceneOverrides(model, integrator));

    /// <summary>
    /// FNV-1a over the bits of every ball's position, velocity, spin, orientation, state and
    /// pocket, and the event count: equal hashes mean equal states bit for bit (up to collisions).
    /// </summary>
    public static ulong Hash(Simulation sim, bool orientation = false)
    {
        ulong h = 14695981039346656037UL;
        void Add(long bits)
        {
            for (int k = 0; k < 8; k++)
            {
                h = (h ^ (ulong)((bits >> (8 * k)) & 0xFF)) * 1099511628211UL;
            }
        }
        void AddDouble(double x) => Add(BitConverter.DoubleToInt64Bits(x));
        foreach (var b in sim.Balls)
        {
            AddDouble(b.Position.X);
            AddDouble(b.Position.Y);
            AddDouble(b.Position.Z);
            AddDouble(b.Velocity.X);
            AddDouble(b.Velocity.Y);
            AddDouble(b.Velocity.Z);
            AddDouble(b.Spin.X);
            AddDouble(b.Spin.Y);
            AddDouble(b.Spin.Z);
            if (orientation)
            {
                Add(BitConverter.SingleToInt32Bits(b.Orientation.X));
                Add(BitConverter.SingleToInt32Bits(b.Orientation.Y));
                Add(BitConverter.SingleToInt32Bits(b.Orientation.Z));
                Add(BitConverter.SingleToInt32Bits(b.Orientation.W));
            }
            Add((long)b.State);
            Add(b.Pocket);
        }
        Add(sim.Events.Count);
        return h;
    }

    /// <summary>Asserts two runs ended in the same state, bit for bit, with the same events.</summary>
    public static void AssertSameRun(Simulation expected, Simulation actual, string because)
    {
        Assert.True(expected.Time == actual.Time, $"{because}: time {actual.Time} != {expected.Time}");
        Assert.True(expected.StepCount == actual.StepCount, $"{because}: steps {actual.StepCount} != {expected.StepCount}");
        Assert.True(expected.EventCapHits == actual.EventCapHits, $"{because}: event cap hits differ");
        var a = expected.Balls;
        var b = actual.Balls;
        Assert.Equal(a.Length, b.Length);
        for (int i = 0; i < a.Length; i++)
        {
            Assert.True(a[i].Position == b[i].Position && a[i].Velocity == b[i].Velocity && a[i].Spin == b[i].Spin
                && a[i].Orientation == b[i].Orientation && a[i].State == b[i].State && a[i].Pocket == b[i].Pocket,
                $"{because}: ball {expected.Ids[i]} differs: {b[i].Position} against {a[i].Position}");
        }
        Assert.Equal(expected.Events.AsSpan().ToArray(), actual.Events.AsSpan().ToArray());
        Assert.Equal(Hash(expected, orientation: true), Hash(actual, orientation: true));
    }
}
