using System.Reflection;
using System.Security.Cryptography;
using System.Text;
using System.Text.Json;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Net;

/// <summary>
/// What the two sides must agree on before a shot: the program's version, the code, and the game
/// the host chose with its physics. The game travels as the record of a game not yet played
/// (<see cref="GameRecordFile"/>: table, physics, models, rack seed, players); its hash is of the
/// table and physics blocks as each side writes them, so a joiner whose build reads the physics
/// differently (another model, a parameter it does not know) computes another hash and refuses.
/// </summary>
public static class Handshake
{
    /// <summary>How long a side waits for the other's hello.</summary>
    public static readonly TimeSpan Timeout = TimeSpan.FromSeconds(5);

    /// <summary>This program's version, as <c>billiards --version</c> prints it.</summary>
    public static string ProgramVersion { get; } = Version(typeof(Handshake).Assembly);

    private static string Version(Assembly assembly)
    {
        string v = assembly.GetCustomAttribute<AssemblyInformationalVersionAttribute>()?.InformationalVersion ?? assembly.GetName().Version?.ToString() ?? "0";
        int plus = v.IndexOf('+', StringComparison.Ordinal);
        return plus < 0 ? v : v[..plus];
    }

    /// <summary>The host's description of <paramref name="setup"/> for its hello.</summary>
    public static HostGame Describe(GameSetup setup)
    {
        ArgumentNullException.ThrowIfNull(setup);
        string record = Encoding.UTF8.GetString(GameRecordFile.ToUtf8(new Match(setup), indented: false)).TrimEnd('\n');
        var (models, hash) = Fingerprint(record);
        return new HostGame(record, models, hash, setup.Start.Players.First, setup.Start.Players.Second);
    }

    /// <summary>The physics' models (the physics block, for messages) and the hash of the table and physics blocks of a record's JSON.</summary>
    public static (string Models, string Hash) Fingerprint(string record)
    {
        using var doc = JsonDocument.Parse(record);
        string table = doc.RootElement.GetProperty("table").GetRawText();
        string physics = doc.RootElement.TryGetProperty("physics", out var p) ? p.GetRawText() : "{}";
        string models = p.ValueKind == JsonValueKind.Object && p.TryGetProperty("models", out var m) ? m.GetRawText() : physics;
        return (MessageCodec.Clip(models), Convert.ToHexStringLower(SHA256.HashData(Encoding.UTF8.GetBytes(table + "\n" + physics))));
    }

    /// <summary>
    /// The joiner's reading of the host's game: its setup, or the one line saying what differs
    /// (the record unreadable here, or its physics hashing otherwise when written again here).
    /// </summary>
    public static (GameSetup? Setup, string? Problem) Read(HostGame game)
    {
        ArgumentNullException.ThrowIfNull(game);
        GameRecord record;
        try
        {
            record = GameRecordFile.Parse(game.Scene, "the host's game");
        }
        catch (SceneException e)
        {
            return (null, $"physics differ: this program cannot read the host's game ({CommandLineText(e.Message)})");
        }
        var (models, hash) = Fingerprint(Encoding.UTF8.GetString(GameRecordFile.ToUtf8(new Match(record.Setup), indented: false)));
        if (hash != game.Hash)
        {
            return (null, $"physics differ: the host's {game.Models} hash {game.Hash[..12]}, here {models} hash {hash[..12]}");
        }
        if (Core.Rules.Seat.Parse(game.FirstPlayer, 0) is null || Core.Rules.Seat.Parse(game.SecondPlayer, 1) is null)
        {
            return (null, "the host's players are not names of 1-24 characters");
        }
        var setup = record.Setup;
        return (setup with { Start = setup.Start with { Players = new Core.Rules.PerPlayer<string>(game.FirstPlayer, game.SecondPlayer) } }, null);
    }

    /// <summary>Why the two hellos cannot play together (one line naming what differs), or null.</summary>
    public static string? Mismatch(Hello mine, Hello theirs)
    {
        ArgumentNullException.ThrowIfNull(mine);
        ArgumentNullException.ThrowIfNull(theirs);
        if (mine.Program != theirs.Program)
        {
            return $"version differs: billiards {MessageCodec.Clip(theirs.Program)} there, {mine.Program} here";
        }
        return mine.Code != theirs.Code ? $"wrong code \"{MessageCodec.Clip(theirs.Code)}\"" : null;
    }

    private static string CommandLineText(string s) => MessageCodec.Clip(s.Replace('\n', ' '));
}
