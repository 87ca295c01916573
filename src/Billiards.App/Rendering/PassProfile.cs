namespace Billiards.App.Rendering;

/// <summary>
/// Where a frame's time goes, pass by pass: at each mark the GL work queued so far is finished
/// (glFinish), and the wall time and the process's CPU time (every thread, a software
/// rasteriser's included) since the previous mark are added to that mark's name. Finishing after
/// every pass costs the overlap of CPU and GPU, so a profiled frame is slower than a plain one;
/// the split between passes is what it is for. CPU time holds on a loaded machine, wall time not.
/// </summary>
internal sealed class PassProfile
{
    private readonly Action _finish;
    private readonly Dictionary<string, (double Wall, double Cpu, long Count)> _passes = [];
    private readonly List<string> _order = [];
    private double _wall, _cpu;

    public PassProfile(Action finish)
    {
        _finish = finish;
        (_wall, _cpu) = (Wall(), Platform.CpuClock.ProcessSeconds());
    }

    /// <summary>Frames marked (<see cref="Frame"/>).</summary>
    public long Frames { get; private set; }

    /// <summary>Finishes the GL work and charges the time since the last mark to <paramref name="name"/>.</summary>
    public void Mark(string name)
    {
        name = Tag + name;
        _finish();
        double wall = Wall(), cpu = Platform.CpuClock.ProcessSeconds();
        if (!_passes.TryGetValue(name, out var sum))
        {
            _order.Add(name);
        }
        _passes[name] = (sum.Wall + wall - _wall, sum.Cpu + cpu - _cpu, sum.Count + 1);
        (_wall, _cpu) = (wall, cpu);
    }

    /// <summary>Put before the names marked (a frame's kind).</summary>
    public string Tag { get; set; } = "";

    /// <summary>Counts a frame.</summary>
    public void Frame() => Frames++;

    /// <summary>Per pass: mean wall and CPU time a frame (ms) and how many frames ran it.</summary>
    public IEnumerable<(string Pass, double WallMs, double CpuMs, long Count)> PerFrame() =>
        _order.Select(n => (n, 1000 * _passes[n].Wall / Math.Max(1, Frames), 1000 * _passes[n].Cpu / Math.Max(1, Frames), _passes[n].Count));

    private static double Wall() => System.Diagnostics.Stopwatch.GetTimestamp() / (double)System.Diagnostics.Stopwatch.Frequency;
}
