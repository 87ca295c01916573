using System.Runtime.InteropServices;

namespace Billiards.App.Platform;

/// <summary>
/// Work that must not take the frames' CPU: the computer player's search. It runs on its own
/// thread at the lowest priority the system gives (Linux: nice 19 for that thread alone; Windows:
/// the lowest thread priority), so that a software rasteriser's threads, which want every core,
/// keep drawing while the computer thinks and the search takes what they leave.
/// </summary>
public static partial class BackgroundWork
{
    private const int PrioProcess = 0, Nicest = 19;

    /// <summary>Runs <paramref name="work"/> on a new low-priority thread.</summary>
    public static Task<T> Run<T>(Func<T> work)
    {
        var done = new TaskCompletionSource<T>(TaskCreationOptions.RunContinuationsAsynchronously);
        var thread = new Thread(() =>
        {
            Lower();
            try
            {
                done.SetResult(work());
            }
            catch (Exception e)
            {
                done.SetException(e);
            }
        })
        {
            IsBackground = true,
            Name = "computer player",
        };
        thread.Start();
        return done.Task;
    }

    /// <summary>Lowers the calling thread's priority; true when the system took it.</summary>
    public static bool Lower()
    {
        if (OperatingSystem.IsLinux())
        {
            try
            {
                // setpriority with a thread id changes that thread only (Linux threads are tasks).
                return SetPriority(PrioProcess, GetTid(), Nicest) == 0;
            }
            catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
            {
                return false;
            }
        }
        Thread.CurrentThread.Priority = ThreadPriority.Lowest;
        return true;
    }

    /// <summary>The calling thread's nice value on Linux (for tests), or null elsewhere.</summary>
    public static int? Niceness() => OperatingSystem.IsLinux() ? GetPriority(PrioProcess, GetTid()) : null;

    [LibraryImport("libc", EntryPoint = "setpriority", SetLastError = true)]
    private static partial int SetPriority(int which, int who, int prio);

    [LibraryImport("libc", EntryPoint = "getpriority", SetLastError = true)]
    private static partial int GetPriority(int which, int who);

    [LibraryImport("libc", EntryPoint = "gettid")]
    private static partial int GetTid();
}
