using System.Collections.Concurrent;
using System.Diagnostics;
using System.Globalization;
using System.Net.Sockets;
using System.Threading.Channels;

namespace Billiards.App.Net;

/// <summary>The protocol's limits (docs/network.md, "Security limits").</summary>
/// <param name="Idle">Longest silence before the peer is dropped (pings keep a live one talking).</param>
/// <param name="FrameDeadline">Longest a frame may take from its first byte to its last.</param>
/// <param name="PingEvery">How often a ping is sent.</param>
/// <param name="Burst">Messages the peer may send at once.</param>
/// <param name="PerSecond">Messages a second the peer may send, on average.</param>
public sealed record NetLimits(TimeSpan Idle, TimeSpan FrameDeadline, TimeSpan PingEvery, int Burst, double PerSecond)
{
    /// <summary>Longest the host waits for a joiner's hello (<see cref="Handshake.Timeout"/> by default).</summary>
    public TimeSpan HelloWithin { get; init; } = Handshake.Timeout;

    /// <summary>The game's limits: 15 s silent, 5 s a frame, a ping a second, 100 messages at once, 50 a second.</summary>
    public static NetLimits Default { get; } = new(TimeSpan.FromSeconds(15), TimeSpan.FromSeconds(5), TimeSpan.FromSeconds(1), 100, 50);
}

/// <summary>
/// One peer over TCP. A background task reads frames, parses and checks each message
/// (<see cref="MessageCodec.Parse"/>) and queues it; the game loop takes them with
/// <see cref="TryReceive"/> and never waits. Sends are queued too and written by another task.
/// Any protocol error (a bad frame, a bad message, a flood, a silent peer) is one log line and a
/// closed connection; pings are answered here and measure <see cref="RoundTripMs"/>.
/// </summary>
public sealed class Connection : IDisposable
{
    private readonly TcpClient _client;
    private readonly NetworkStream _stream;
    private readonly NetLimits _limits;
    private readonly Action<string> _log;
    private readonly ConcurrentQueue<Message> _inbox = new();
    private readonly Channel<byte[]> _outbox = Channel.CreateBounded<byte[]>(new BoundedChannelOptions(256) { FullMode = BoundedChannelFullMode.DropWrite, SingleReader = true });
    private readonly CancellationTokenSource _stop = new();
    private readonly Stopwatch _clock = Stopwatch.StartNew();
    private readonly Task _reader, _writer;
    private double _tokens;
    private double _lastRefill;
    private long _pingId;
    private long _pingSent = -1;
    private double _pingAt;
    private string? _closed;
    private string? _closing;
    private bool _greeted;
    private readonly SemaphoreSlim _arrived = new(0);

    /// <summary>Starts reading and writing on <paramref name="client"/>, a connected socket.</summary>
    /// <param name="client">The connected socket (the connection owns it).</param>
    /// <param name="name">The peer's name in log lines (its address).</param>
    /// <param name="log">Where the log lines go (any thread).</param>
    /// <param name="limits">The limits; <see cref="NetLimits.Default"/> when null.</param>
    public Connection(TcpClient client, string name, Action<string> log, NetLimits? limits = null)
    {
        ArgumentNullException.ThrowIfNull(client);
        ArgumentNullException.ThrowIfNull(log);
        _client = client;
        _client.NoDelay = true;
        _stream = client.GetStream();
        _limits = limits ?? NetLimits.Default;
        _tokens = _limits.Burst;
        _log = log;
        Name = name;
        _reader = Task.Run(ReadLoop);
        _writer = Task.Run(WriteLoop);
    }

    /// <summary>The peer's name in log lines.</summary>
    public string Name { get; }

    /// <summary>True until either side closes.</summary>
    public bool IsOpen => Volatile.Read(ref _closed) is null && Volatile.Read(ref _closing) is null;

    /// <summary>Why the connection closed, or null while open.</summary>
    public string? ClosedBecause => Volatile.Read(ref _closed) ?? Volatile.Read(ref _closing);

    /// <summary>The last round trip of a ping (ms), or null before the first answer.</summary>
    public double? RoundTripMs { get; private set; }

    /// <summary>Messages received and checked so far (pings included).</summary>
    public int Received { get; private set; }

    /// <summary>Takes the next checked message, without waiting.</summary>
    public bool TryReceive(out Message message) => _inbox.TryDequeue(out message!);

    private void Arrived(Message message)
    {
        _inbox.Enqueue(message);
        _arrived.Release();
    }

    /// <summary>Queues <paramref name="message"/> to be sent (never waits; dropped once closed).</summary>
    public void Send(Message message)
    {
        if (!IsOpen)
        {
            return;
        }
        var json = MessageCodec.Write(message);
        if (json.Length > Framing.MaxMessageBytes)
        {
            // Never sent half: a game too long for one message is not sent at all.
            _log($"net: {Name}: not sent: a {message.Kind} of {json.Length} bytes is over the limit of {Framing.MaxMessageBytes}");
            return;
        }
        _outbox.Writer.TryWrite(Framing.Frame(json));
    }

    /// <summary>Sends <paramref name="reason"/> as a bye and closes once it is written (within the frame deadline); never waits.</summary>
    public void Close(string reason)
    {
        if (!IsOpen || Interlocked.CompareExchange(ref _closing, reason, null) is not null)
        {
            return;
        }
        _outbox.Writer.TryWrite(Framing.Frame(MessageCodec.Write(new Bye(reason))));
        _outbox.Writer.TryComplete();
        _ = Task.Run(async () =>
        {
            // Let the writer flush the bye, briefly.
            await Task.WhenAny(_writer, Task.Delay(_limits.FrameDeadline)).ConfigureAwait(false);
            Shut($"closed: {reason}", log: false);
        });
    }

    /// <summary>Waits for the first message (the hello), up to <paramref name="timeout"/>; null when none came or the connection closed.</summary>
    public Message? WaitFirst(TimeSpan timeout) => WaitFirstAsync(timeout).GetAwaiter().GetResult();

    /// <summary>Waits for the first message without holding a thread (the host's handshakes).</summary>
    public async Task<Message?> WaitFirstAsync(TimeSpan timeout)
    {
        if (TryReceive(out var m))
        {
            return m;
        }
        await _arrived.WaitAsync(timeout).ConfigureAwait(false);
        return TryReceive(out m) ? m : null;
    }

    /// <summary>
    /// How the reader stands, for a log line when a peer seems silent: when its task started (ms
    /// after the connection), the messages it has read, and whether it has ended; with the thread
    /// pool's threads and queued work items at the moment of asking.
    /// </summary>
    public string ReaderState
    {
        get
        {
            double started = Volatile.Read(ref _readerStartedMs);
            string reader = started < 0 ? "not started" : string.Create(CultureInfo.InvariantCulture, $"started at {started:0} ms");
            string state = _reader.IsCompleted ? (_reader.IsFaulted ? "faulted" : "ended") : "running";
            return string.Create(CultureInfo.InvariantCulture,
                $"reader {reader}, {state}, {Received} messages read; pool: {ThreadPool.ThreadCount} threads, {ThreadPool.PendingWorkItemCount} queued");
        }
    }

    private double _readerStartedMs = -1;

    private async Task ReadLoop()
    {
        Volatile.Write(ref _readerStartedMs, _clock.Elapsed.TotalMilliseconds);
        try
        {
            while (!_stop.IsCancellationRequested)
            {
                var body = await Framing.ReadAsync(_stream, _limits.Idle, _limits.FrameDeadline, _stop.Token).ConfigureAwait(false);
                if (body is null)
                {
                    Shut("the peer closed the connection", log: true);
                    return;
                }
                if (!TakeToken())
                {
                    throw new ProtocolException($"flood: more than {_limits.Burst} messages at once ({_limits.PerSecond:0} a second allowed)");
                }
                var message = MessageCodec.Parse(body);
                Received++;
                if (!_greeted && message is not Ping)
                {
                    // Pings may come first (the other side's writer pings while it waits); then the hello.
                    _greeted = message is Hello or Bye ? true : throw new ProtocolException($"expected a hello first, not {message.Kind}");
                }
                switch (message)
                {
                    case Ping { Reply: false } p:
                        Send(p with { Reply = true });
                        break;
                    case Ping { Reply: true } p:
                        if (p.Id == Interlocked.Read(ref _pingSent))
                        {
                            RoundTripMs = (_clock.Elapsed.TotalMilliseconds) - _pingAt;
                        }
                        break;
                    case Bye b:
                        Arrived(b);
                        Shut($"the peer said bye: {MessageCodec.Clip(b.Reason)}", log: true);
                        return;
                    default:
                        Arrived(message);
                        break;
                }
            }
        }
        catch (ProtocolException e)
        {
            // A bye names what was wrong, so that a well-meaning peer's log says it too.
            Send(new Bye(e.Message));
            _outbox.Writer.TryComplete();
            await Task.WhenAny(_writer, Task.Delay(500)).ConfigureAwait(false);
            Shut($"closed: {e.Message}", log: true);
        }
        catch (Exception e) when (e is IOException or SocketException or ObjectDisposedException or OperationCanceledException)
        {
            Shut($"connection lost ({e.GetType().Name})", log: !_stop.IsCancellationRequested);
        }
    }

    private async Task WriteLoop()
    {
        try
        {
            var reader = _outbox.Reader;
            while (!_stop.IsCancellationRequested)
            {
                using var tick = CancellationTokenSource.CreateLinkedTokenSource(_stop.Token);
                tick.CancelAfter(_limits.PingEvery);
                byte[] frame;
                try
                {
                    if (!await reader.WaitToReadAsync(tick.Token).ConfigureAwait(false))
                    {
                        return;
                    }
                    if (!reader.TryRead(out frame!))
                    {
                        continue;
                    }
                }
                catch (OperationCanceledException) when (!_stop.IsCancellationRequested)
                {
                    long id = Interlocked.Increment(ref _pingId);
                    _pingAt = _clock.Elapsed.TotalMilliseconds;
                    Interlocked.Exchange(ref _pingSent, id);
                    frame = Framing.Frame(MessageCodec.Write(new Ping(id, false)));
                }
                using var deadline = CancellationTokenSource.CreateLinkedTokenSource(_stop.Token);
                deadline.CancelAfter(_limits.FrameDeadline);
                await _stream.WriteAsync(frame, deadline.Token).ConfigureAwait(false);
            }
        }
        catch (Exception e) when (e is IOException or SocketException or ObjectDisposedException or OperationCanceledException)
        {
            Shut($"connection lost while sending ({e.GetType().Name})", log: !_stop.IsCancellationRequested);
        }
    }

    private bool TakeToken()
    {
        double now = _clock.Elapsed.TotalSeconds;
        _tokens = Math.Min(_limits.Burst, _tokens + ((now - _lastRefill) * _limits.PerSecond));
        _lastRefill = now;
        if (_tokens < 1)
        {
            return false;
        }
        _tokens--;
        return true;
    }

    private void Shut(string why, bool log)
    {
        if (Interlocked.CompareExchange(ref _closed, why, null) is not null)
        {
            return;
        }
        if (log)
        {
            _log($"net: {Name}: {why}");
        }
        _stop.Cancel();
        _outbox.Writer.TryComplete();
        _client.Close();
        // A waiter for the first message wakes to find none.
        _arrived.Release();
    }

    /// <inheritdoc />
    public void Dispose()
    {
        Shut("closed", log: false);
        Task.WaitAll([_reader, _writer], TimeSpan.FromSeconds(2));
        _stop.Dispose();
        _client.Dispose();
    }
}
