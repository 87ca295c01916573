using System.Net;
using System.Net.Sockets;

namespace Billiards.App.Net;

/// <summary>
/// The host's listener: accepts connections on a background task, takes each one's hello within
/// <see cref="NetLimits.HelloWithin"/> (<see cref="Handshake.Timeout"/>) and admits one peer with the right version and code (a peer that
/// dropped may come back the same way). Everything else is refused with one log line and a bye
/// naming why. At most <see cref="MaxPending"/> connections are in their handshake at once; more
/// are closed at once.
/// </summary>
public sealed class NetHost : IDisposable
{
    /// <summary>Connections in their handshake at once.</summary>
    public const int MaxPending = 16;

    private readonly TcpListener _listener;
    private readonly Func<Hello> _hello;
    private readonly Action<string> _log;
    private readonly NetLimits? _limits;
    private readonly CancellationTokenSource _stop = new();
    private readonly Task _accepting;
    private int _pending;
    private Connection? _peer;

    /// <summary>Listens on <paramref name="address"/>:<paramref name="port"/> (0: the system chooses).</summary>
    /// <param name="address">The address to listen on.</param>
    /// <param name="port">The port, or 0.</param>
    /// <param name="hello">The host's hello at the moment a peer is admitted (the game and its shots so far).</param>
    /// <param name="log">Where log lines go.</param>
    /// <param name="limits">The connection limits, or null for the defaults.</param>
    public NetHost(IPAddress address, int port, Func<Hello> hello, Action<string> log, NetLimits? limits = null)
    {
        ArgumentNullException.ThrowIfNull(hello);
        ArgumentNullException.ThrowIfNull(log);
        _hello = hello;
        _log = log;
        _limits = limits;
        _listener = new TcpListener(address, port);
        try
        {
            _listener.Start();
        }
        catch (SocketException e)
        {
            throw new Cli.EnvironmentException($"host: cannot listen on {address}:{port}: {e.Message}", e);
        }
        Port = ((IPEndPoint)_listener.LocalEndpoint).Port;
        _accepting = Task.Run(AcceptLoop);
    }

    /// <summary>The port listened on.</summary>
    public int Port { get; }

    /// <summary>Peers admitted so far (a peer coming back counts again).</summary>
    public int Admitted { get; private set; }

    /// <summary>Connections refused so far.</summary>
    public int Refused { get; private set; }

    /// <summary>The admitted peer while it is connected, else null.</summary>
    public Connection? Peer => Volatile.Read(ref _peer) is { IsOpen: true } p ? p : null;

    /// <summary>Signal (on a background thread): a peer was admitted, with its hello.</summary>
    public event Action<Connection, Hello>? PeerAdmitted;

    private async Task AcceptLoop()
    {
        while (!_stop.IsCancellationRequested)
        {
            TcpClient client;
            try
            {
                client = await _listener.AcceptTcpClientAsync(_stop.Token).ConfigureAwait(false);
            }
            catch (Exception e) when (e is OperationCanceledException or ObjectDisposedException or SocketException)
            {
                return;
            }
            string name = client.Client.RemoteEndPoint?.ToString() ?? "peer";
            if (Interlocked.Increment(ref _pending) > MaxPending)
            {
                Interlocked.Decrement(ref _pending);
                Refused++;
                _log($"net: {name}: refused: too many connections at once");
                client.Dispose();
                continue;
            }
            _ = Admit(client, name);
        }
    }

    private async Task Admit(TcpClient client, string name)
    {
        Connection? connection = null;
        try
        {
            connection = new Connection(client, name, _log, _limits);
            var within = (_limits ?? NetLimits.Default).HelloWithin;
            var first = await connection.WaitFirstAsync(within).ConfigureAwait(false);
            if (first is null)
            {
                if (connection.IsOpen)
                {
                    // How the reader stood says whether the peer was silent or its frame went unread.
                    _log($"net: {name}: no hello within {within.TotalSeconds:0} s: {connection.ReaderState}");
                    Refuse(connection, $"no hello within {within.TotalSeconds:0} s");
                }
                else
                {
                    Refused++;
                }
                return;
            }
            if (first is not Hello hello || hello.Game is not null)
            {
                Refuse(connection, $"expected a joiner's hello first, not {first.Kind}{(first is Hello ? " with a game" : "")}");
                return;
            }
            var mine = _hello();
            if (Handshake.Mismatch(mine, hello) is { } problem)
            {
                Refuse(connection, problem);
                return;
            }
            lock (_listener)
            {
                if (Peer is not null)
                {
                    Refuse(connection, "a game is in progress with another player");
                    return;
                }
                Volatile.Write(ref _peer, connection);
            }
            Admitted++;
            connection.Send(mine);
            _log($"net: {name}: joined");
            PeerAdmitted?.Invoke(connection, hello);
        }
        catch (Exception e) when (e is IOException or SocketException or ObjectDisposedException or InvalidOperationException)
        {
            _log($"net: {name}: dropped during the handshake ({e.GetType().Name})");
            connection?.Dispose();
        }
        finally
        {
            // A refused connection closes itself once its bye is written.
            Interlocked.Decrement(ref _pending);
        }
    }

    private void Refuse(Connection connection, string why)
    {
        Refused++;
        _log($"net: {connection.Name}: refused: {why}");
        connection.Close($"refused: {why}");
    }

    /// <inheritdoc />
    public void Dispose()
    {
        _stop.Cancel();
        _listener.Stop();
        _accepting.Wait(TimeSpan.FromSeconds(2));
        Volatile.Read(ref _peer)?.Dispose();
        _stop.Dispose();
    }
}
