using System.Collections.Concurrent;
using System.Runtime.InteropServices;

namespace Billiards.App.Platform;

/// <summary>
/// Work that must not take the frames' CPU: the computer player's search. It runs on a small pool
/// of threads of its own, each at the lowest priority the system gives (Linux: nice 19 for that
/// thread alone; Windows: the lowest thread priority), so that a software rasteriser's threads,
/// which want every core, keep drawing while the computer thinks and the search takes what they
/// leave. Parallel loops inside the work run on the same low-priority threads (they are the
/// work's <see cref="TaskScheduler.Current"/>), never on the shared thread pool.
/// </summary>
/// <remarks>
/// Poll the returned task (<see cref="Task.IsCompleted"/>) from the frame loop rather than awaiting
/// it: on Linux a thread inherits the nice value of the thread that creates it, so continuations
/// started from these threads could leave a thread-pool thread at the lowest priority.
/// </remarks>
public static partial class BackgroundWork
{
    private const int PrioProcess = 0, Nicest = 19;

    private static readonly Lazy<LowPriorityScheduler> Scheduler = new(() => new LowPriorityScheduler(Math.Max(2, Environment.ProcessorCount)));

    /// <summary>Runs <paramref name="work"/> on one of the low-priority threads.</summary>
    public static Task<T> Run<T>(Func<T> work) =>
        Task.Factory.StartNew(work, CancellationToken.None, TaskCreationOptions.DenyChildAttach, Scheduler.Value);

    /// <summary>
    /// Runs <paramref name="work"/>, which blocks (a connect and handshake, a game loop), on a thread
    /// of its own at normal priority, never on the shared thread pool: the connections' readers and
    /// writers run on that pool, and on two cores with every pool thread blocked they would wait
    /// past their own timeouts.
    /// </summary>
    public static Task<T> RunBlocking<T>(Func<T> work) =>
        Task.Factory.StartNew(work, CancellationToken.None, TaskCreationOptions.LongRunning | TaskCreationOptions.DenyChildAttach, TaskScheduler.Default);

    /// <inheritdoc cref="RunBlocking{T}(Func{T})"/>
    public static Task RunBlocking(Action work) =>
        Task.Factory.StartNew(work, CancellationToken.None, TaskCreationOptions.LongRunning | TaskCreationOptions.DenyChildAttach, TaskScheduler.Default);

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

    /// <summary>A fixed set of background threads, each lowered once when it starts.</summary>
    private sealed class LowPriorityScheduler : TaskScheduler
    {
        [ThreadStatic]
        private static bool t_serving;

        private readonly BlockingCollection<Task> _queue = [];
        private readonly int _threads;

        public LowPriorityScheduler(int threads)
        {
            _threads = threads;
            for (int i = 0; i < threads; i++)
            {
                var thread = new Thread(Serve) { IsBackground = true, Name = "computer player " + (i + 1) };
                thread.Start();
            }
        }

        public override int MaximumConcurrencyLevel => _threads;

        private void Serve()
        {
            Lower();
            t_serving = true;
            foreach (var task in _queue.GetConsumingEnumerable())
            {
                TryExecuteTask(task);
            }
        }

        protected override void QueueTask(Task task) => _queue.Add(task);

        // Inline only on these threads, so no task of this scheduler runs at a normal priority.
        protected override bool TryExecuteTaskInline(Task task, bool taskWasPreviouslyQueued) => t_serving && TryExecuteTask(task);

        protected override IEnumerable<Task> GetScheduledTasks() => [.. _queue];
    }
}
