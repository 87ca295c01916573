using System.Net;
using System.Net.Sockets;
using System.Runtime.CompilerServices;
using Billiards.App.Cli;
using Billiards.Core.Rules;

namespace Billiards.App.Net;

/// <summary>The joiner's side of the handshake: connect, say hello with the code, read the host's game.</summary>
public static class NetJoin
{
    /// <summary>How long a connection attempt may take.</summary>
    public static readonly TimeSpan ConnectTimeout = TimeSpan.FromSeconds(5);

    /// <summary>
    /// Connects to <paramref name="host"/>:<paramref name="port"/> and shakes hands: the open
    /// connection, the host's game and its hello (its shots so far, for a joiner coming back).
    /// </summary>
    /// <exception cref="CliException">The host refused (the line names why) or its game differs here (the host is told why).</exception>
    /// <exception cref="EnvironmentException">Nothing listens there, or no answer in time.</exception>
    public static (Connection Connection, GameSetup Setup, Hello HostHello) Connect(string host, int port, string code, Action<string> log, string? program = null, NetLimits? limits = null)
    {
        ArgumentNullException.ThrowIfNull(log);
        var client = new TcpClient();
        try
        {
            if (!client.ConnectAsync(host, port).Wait(ConnectTimeout))
            {
                throw new EnvironmentException($"join: no answer from {host}:{port} within {ConnectTimeout.TotalSeconds:0} s");
            }
        }
        catch (AggregateException e) when (e.InnerException is SocketException s)
        {
            client.Dispose();
            throw new EnvironmentException($"join: cannot connect to {host}:{port}: {s.Message}", s);
        }
        // During the handshake a refusal is this verb's one line: the connection's own line of it is left out.
        var shaking = new StrongBox<bool>(true);
        var connection = new Connection(client, $"{host}:{port}", line =>
        {
            if (!Volatile.Read(ref shaking.Value))
            {
                log(line);
            }
        }, limits);
        var mine = new Hello(program ?? Handshake.ProgramVersion, code, null, 0);
        connection.Send(mine);
        var first = connection.WaitFirst(Handshake.Timeout);
        try
        {
            switch (first)
            {
                case Bye bye:
                    throw new CliException($"join: the host {bye.Reason}");
                case null:
                    throw new EnvironmentException($"join: {connection.ClosedBecause ?? $"no hello from the host within {Handshake.Timeout.TotalSeconds:0} s"}");
                case Hello { Game: { } game } hello:
                    string? problem = Handshake.Mismatch(mine, hello);
                    var (setup, physics) = problem is null ? Handshake.Read(game) : (null, null);
                    problem ??= physics;
                    if (problem is not null)
                    {
                        connection.Close($"refused: {problem}");
                        throw new CliException($"join: refused: {problem}");
                    }
                    Volatile.Write(ref shaking.Value, false);
                    return (connection, setup!, hello);
                default:
                    throw new CliException($"join: expected the host's hello, not {first.Kind}");
            }
        }
        catch
        {
            // A connection closing with a bye closes itself once the bye is written.
            if (connection.IsOpen)
            {
                connection.Dispose();
            }
            throw;
        }
    }

    /// <summary>Splits <c>HOST[:PORT]</c>; only loopback and literal addresses or names are taken as given.</summary>
    /// <exception cref="CliException">An empty host or a port outside 1-65535.</exception>
    public static (string Host, int Port) ParseAddress(string text, int defaultPort)
    {
        ArgumentNullException.ThrowIfNull(text);
        int colon = text.LastIndexOf(':');
        string host = colon < 0 ? text : text[..colon];
        int port = defaultPort;
        if (colon >= 0 && (!int.TryParse(text[(colon + 1)..], out port) || port is < 1 or > 65535))
        {
            throw new CliException($"join {text}: the port must be 1-65535");
        }
        if (host.Length == 0 || host.Any(char.IsWhiteSpace) || host.Any(char.IsControl))
        {
            throw new CliException($"join {text}: expected HOST[:PORT]");
        }
        return (host == "localhost" ? IPAddress.Loopback.ToString() : host, port);
    }
}
