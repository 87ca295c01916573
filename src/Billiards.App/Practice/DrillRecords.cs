using System.Text.Json;
using Billiards.App.Cli;
using Billiards.Core.Practice;

namespace Billiards.App.Practice;

/// <summary>A drill's results kept between runs.</summary>
/// <param name="Attempts">Attempts finished.</param>
/// <param name="Successes">Attempts that met the goal.</param>
/// <param name="BestPotted">The most balls of the sequence potted in one attempt.</param>
/// <param name="BestDistance">The closest an attempt that potted its last ball left the cue ball to the zone's centre (m), made or missed, or null.</param>
public sealed record DrillRecord(int Attempts, int Successes, int BestPotted, double? BestDistance)
{
    /// <summary>No attempt yet.</summary>
    public static DrillRecord None { get; } = new(0, 0, 0, null);

    /// <summary>This record with one more attempt's outcome.</summary>
    public DrillRecord With(DrillOutcome outcome)
    {
        ArgumentNullException.ThrowIfNull(outcome);
        double? best = BestDistance;
        // The closest finish of any attempt that potted its last ball, made or missed: a cue ball
        // 2.6 cm outside the zone is the best so far, which the player aims to better.
        if (outcome is { ZoneDistance: double d } && (best is null || d < best))
        {
            best = d;
        }
        return new DrillRecord(Attempts + 1, Successes + (outcome.Success ? 1 : 0), Math.Max(BestPotted, outcome.Potted), best);
    }
}

/// <summary>
/// Every drill's <see cref="DrillRecord"/>, in <c>drills.json</c> of the data folder
/// (<see cref="DataFolder"/>; format <c>billiards-drill-results/1</c>), written atomically after
/// each attempt so that a crash never leaves half a file.
/// <code>{ "format": "billiards-drill-results/1",
///   "drills": { "stop-shot": { "attempts": 3, "successes": 2, "best_potted": 1, "best_distance": 0.031 } } }</code>
/// </summary>
public sealed class DrillRecords
{
    /// <summary>The format tag.</summary>
    public const string Format = "billiards-drill-results/1";

    /// <summary>The file's name in the data folder.</summary>
    public const string FileName = "drills.json";

    private readonly Dictionary<string, DrillRecord> _records;

    private DrillRecords(string path, Dictionary<string, DrillRecord> records)
    {
        Path = path;
        _records = records;
    }

    /// <summary>The results file.</summary>
    public string Path { get; }

    /// <summary>The record of a drill (<see cref="DrillRecord.None"/> before its first attempt).</summary>
    public DrillRecord this[string drill] => _records.TryGetValue(drill, out var r) ? r : DrillRecord.None;

    /// <summary>
    /// The records in <paramref name="path"/>; none when there is no file, and none for a file that
    /// cannot be read (one line on <paramref name="warnings"/>: a broken file never stops the game,
    /// and is replaced at the next attempt).
    /// </summary>
    public static DrillRecords Load(string path, TextWriter? warnings = null)
    {
        var records = new Dictionary<string, DrillRecord>(StringComparer.Ordinal);
        if (!File.Exists(path))
        {
            return new DrillRecords(path, records);
        }
        try
        {
            using var doc = JsonDocument.Parse(File.ReadAllText(path));
            var root = doc.RootElement;
            if (root.GetProperty("format").GetString() != Format)
            {
                throw new InvalidOperationException($"not {Format}");
            }
            foreach (var drill in root.GetProperty("drills").EnumerateObject())
            {
                var e = drill.Value;
                double? best = e.TryGetProperty("best_distance", out var b) && b.ValueKind == JsonValueKind.Number ? b.GetDouble() : null;
                records[drill.Name] = new DrillRecord(e.GetProperty("attempts").GetInt32(), e.GetProperty("successes").GetInt32(), e.GetProperty("best_potted").GetInt32(), best);
            }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or JsonException or InvalidOperationException or KeyNotFoundException or FormatException)
        {
            warnings?.WriteLine($"billiards: {path}: cannot read the drill results ({e.Message}); starting afresh");
            records.Clear();
        }
        return new DrillRecords(path, records);
    }

    /// <summary>Counts an attempt's outcome and writes the file (its folder created); a failure to write is one line on <paramref name="warnings"/>.</summary>
    public DrillRecord Record(string drill, DrillOutcome outcome, TextWriter? warnings = null)
    {
        var record = this[drill].With(outcome);
        _records[drill] = record;
        try
        {
            Directory.CreateDirectory(System.IO.Path.GetDirectoryName(System.IO.Path.GetFullPath(Path))!);
            OutputFiles.Write(Path, ToUtf8());
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            warnings?.WriteLine($"billiards: {Path}: cannot save the drill results ({e.Message})");
        }
        return record;
    }

    private byte[] ToUtf8()
    {
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true }))
        {
            w.WriteStartObject();
            w.WriteString("format", Format);
            w.WriteStartObject("drills");
            foreach (var (name, r) in _records.OrderBy(p => p.Key, StringComparer.Ordinal))
            {
                w.WriteStartObject(name);
                w.WriteNumber("attempts", r.Attempts);
                w.WriteNumber("successes", r.Successes);
                w.WriteNumber("best_potted", r.BestPotted);
                if (r.BestDistance is double d)
                {
                    w.WriteNumber("best_distance", d);
                }
                else
                {
                    w.WriteNull("best_distance");
                }
                w.WriteEndObject();
            }
            w.WriteEndObject();
            w.WriteEndObject();
        }
        stream.WriteByte((byte)'\n');
        return stream.ToArray();
    }
}
