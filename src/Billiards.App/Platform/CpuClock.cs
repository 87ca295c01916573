using System.Runtime.InteropServices;

namespace Billiards.App.Platform;

/// <summary>
/// The processor time this process has used (s), every thread's together (a software
/// rasteriser's drawing threads included). Unlike a frame's wall time it does not grow when
/// other programs take the cores, so a frame's cost read from it holds on a busy machine.
/// </summary>
public static partial class CpuClock
{
    private const int ProcessCpuClock = 2; // CLOCK_PROCESS_CPUTIME_ID

    /// <summary>The process's processor time (s): to the nanosecond on Linux, to the system's tick elsewhere.</summary>
    public static double ProcessSeconds()
    {
        if (OperatingSystem.IsLinux())
        {
            try
            {
                if (ClockGetTime(ProcessCpuClock, out var t) == 0)
                {
                    return t.Seconds + (t.Nanoseconds * 1e-9);
                }
            }
            catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
            {
                // Fall through to the portable reading.
            }
        }
        using var process = System.Diagnostics.Process.GetCurrentProcess();
        return process.TotalProcessorTime.TotalSeconds;
    }

    [StructLayout(LayoutKind.Sequential)]
    private struct TimeSpec
    {
        public long Seconds;
        public long Nanoseconds;
    }

    [LibraryImport("libc", EntryPoint = "clock_gettime")]
    private static partial int ClockGetTime(int clock, out TimeSpec time);
}
