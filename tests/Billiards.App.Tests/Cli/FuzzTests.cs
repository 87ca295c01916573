using System.Globalization;
using System.Text;
using System.Text.Json;
using System.Text.Json.Nodes;
using Billiards.App.Cli;
using Billiards.Core.Mathematics;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.App.Tests.Cli;

/// <summary>
/// A seeded, bounded fuzz of the command line, in-process through <see cref="CommandLine.Run"/>:
/// the shipped scenes mutated (wrong types, missing and unknown fields, non-finite and extreme
/// numbers, huge arrays, deep nesting, truncation, garbage bytes, a byte order mark) and the
/// command lines of the verbs mutated (missing, repeated, unknown and odd arguments). Every
/// outcome must be a clean refusal (exit 2, or 1 for the environment; one line on stderr, no
/// stack trace, no internal error, nothing on stdout, no file left behind) or a valid result
/// (exit 0; a result whose balls are all on the table or pocketed).
/// </summary>
public sealed class FuzzTests : IDisposable
{
    private const int Seed = 20261130;
    private const int Cases = 1000;

    private readonly string _dir = Directory.CreateTempSubdirectory("billiards-fuzz-").FullName;
    private readonly Random _random = new(Seed);
    private readonly List<string> _scenes = [.. Directory.GetFiles(AssetFolder.Scene(""), "*.json", SearchOption.AllDirectories).Order(StringComparer.Ordinal).Select(File.ReadAllText)];

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    [Fact]
    public void EveryMutatedSceneAndCommandLineIsACleanRefusalOrAValidResult()
    {
        var outcomes = new Dictionary<int, int>();
        for (int i = 0; i < Cases; i++)
        {
            string scene = Path.Combine(_dir, $"case{i}.json");
            File.WriteAllBytes(scene, MutateScene(_scenes[_random.Next(_scenes.Count)]));
            string[] args = CommandLineFor(scene, i);
            var (code, stdout, stderr) = CliRun.Run(args);
            string what = $"case {i}: billiards {string.Join(' ', args.Select(a => a.Length > 60 ? a[..60] + "..." : a))}";
            outcomes[code] = outcomes.GetValueOrDefault(code) + 1;
            if (code == 0)
            {
                AssertValidResult(args, stdout, what);
            }
            else
            {
                Assert.True(code is CommandLine.BadInput or CommandLine.Failure, $"{what}: exit {code}");
                Assert.True(stdout.Length == 0, $"{what}: refused but wrote to stdout");
                string[] lines = stderr.TrimEnd('\n').Split('\n');
                Assert.True(lines.Length == 1 && lines[0].Length > 0, $"{what}: stderr is not one line: {stderr}");
                Assert.DoesNotContain("   at ", stderr);
                Assert.False(stderr.Contains("internal error", StringComparison.Ordinal), $"{what}: {stderr}");
            }
            Assert.Empty(Directory.GetFiles(_dir, "*.tmp-*", SearchOption.AllDirectories));
            File.Delete(scene);
        }
        // The generator reaches both kinds of outcome, or it tests little.
        Assert.True(outcomes.GetValueOrDefault(0) > 60, $"only {outcomes.GetValueOrDefault(0)} valid results");
        Assert.True(outcomes.GetValueOrDefault(CommandLine.BadInput) > 300, $"only {outcomes.GetValueOrDefault(CommandLine.BadInput)} refusals");
    }

    private static void AssertValidResult(string[] args, string stdout, string what)
    {
        // What the case wrote: stdout, or the file its (possibly mutated) --out named, which may
        // be relative to the working folder; it is read and removed.
        string? file = OutValue(args) is { } o ? Path.GetFullPath(o) : null;
        bool wroteFile = file is not null && File.Exists(file);
        if (args[0] != "simulate")
        {
            Assert.True(wroteFile, $"{what}: exit 0 without its file");
            File.Delete(file!);
            return;
        }
        Assert.True(stdout.Length > 0 || wroteFile, $"{what}: exit 0, but no result on stdout or in its --out file");
        string json = stdout.Length > 0 ? stdout : File.ReadAllText(file!);
        if (stdout.Length == 0)
        {
            File.Delete(file!);
        }
        using var result = JsonDocument.Parse(json);
        var root = result.RootElement;
        Assert.Equal("billiards-result/1", root.GetProperty("format").GetString());
        var scene = SceneLoader.Load(args[1], Overrides(args));
        foreach (var ball in root.GetProperty("balls").EnumerateArray())
        {
            var p = ball.GetProperty("position").EnumerateArray().Select(x => x.GetDouble()).ToArray();
            // Pocketed, off the table over a rail (out of play where it came down), or on the bed.
            string? state = ball.GetProperty("state").GetString();
            bool outOfPlay = state is "pocketed" or "off-table";
            Assert.True(outOfPlay || TableBounds.Contains(scene.Table, new Vec3(p[0], p[1], p[2]), scene.BallRadius),
                $"{what}: ball {ball.GetProperty("id").GetString()} ended {state} outside the table at [{p[0]}, {p[1]}]");
        }
    }

    // The value of the last --out, as "--out VALUE" or "--out=VALUE" (an empty "=" takes the next word).
    private static string? OutValue(string[] args)
    {
        string? value = null;
        for (int k = 0; k < args.Length; k++)
        {
            if (args[k] == "--out" && k + 1 < args.Length)
            {
                value = args[k + 1];
            }
            else if (args[k].StartsWith("--out=", StringComparison.Ordinal))
            {
                value = args[k].Length > 6 ? args[k][6..] : k + 1 < args.Length ? args[k + 1] : null;
            }
        }
        return value;
    }

    private static SceneOverrides Overrides(string[] args)
    {
        string? Get(string option) => Array.IndexOf(args, option) is var i and >= 0 && i + 1 < args.Length ? args[i + 1] : null;
        return new SceneOverrides(Get("--model"), Get("--integrator"), Get("--dt") is { } dt ? double.Parse(dt, CultureInfo.InvariantCulture) : null);
    }

    // ---- scenes ----

    private byte[] MutateScene(string text)
    {
        // Some scenes stay whole, so that the command-line mutations also meet valid scenes.
        int mutations = _random.Next(10) < 3 ? 0 : 1 + _random.Next(3);
        for (int m = 0; m < mutations; m++)
        {
            text = _random.Next(10) switch
            {
                < 6 => MutateTree(text),
                _ => MutateText(text),
            };
        }
        byte[] bytes = Encoding.UTF8.GetBytes(text);
        if (_random.Next(12) == 0)
        {
            bytes = [0xEF, 0xBB, 0xBF, .. bytes]; // a UTF-8 byte order mark
        }
        if (_random.Next(40) == 0)
        {
            bytes = new byte[_random.Next(200)];
            _random.NextBytes(bytes); // garbage
        }
        return bytes;
    }

    private string MutateTree(string text)
    {
        JsonNode? root;
        try
        {
            root = JsonNode.Parse(text);
        }
        catch (JsonException)
        {
            return text;
        }
        if (root is null)
        {
            return text;
        }
        var nodes = new List<JsonNode>();
        Collect(root, nodes);
        var target = nodes[_random.Next(nodes.Count)];
        var parent = target.Parent;
        switch (_random.Next(9))
        {
            case 0 when parent is JsonObject o:
                o.Remove(target.GetPropertyName()); // a missing field
                break;
            case 1 when target is JsonObject o:
                o[RandomName()] = RandomValue(0); // an unknown field
                break;
            case 2 when target is JsonArray a:
                int n = _random.Next(2) == 0 ? _random.Next(4) : 1000 + _random.Next(20000);
                a.Clear();
                for (int i = 0; i < n; i++)
                {
                    a.Add(_random.Next(2) == 0 ? RandomNumber() : RandomValue(1)); // huge or odd arrays
                }
                break;
            case 3:
                Replace(target, Nest(RandomValue(0), 10 + _random.Next(300))); // deep nesting
                break;
            case 4 or 5:
                Replace(target, RandomNumber());
                break;
            default:
                Replace(target, RandomValue(0)); // another type
                break;
        }
        return root.ToJsonString();
    }

    private static void Collect(JsonNode node, List<JsonNode> nodes)
    {
        nodes.Add(node);
        if (node is JsonObject o)
        {
            foreach (var (_, child) in o.ToList())
            {
                if (child is not null)
                {
                    Collect(child, nodes);
                }
            }
        }
        else if (node is JsonArray a)
        {
            foreach (var child in a.ToList())
            {
                if (child is not null)
                {
                    Collect(child, nodes);
                }
            }
        }
    }

    private static void Replace(JsonNode target, JsonNode? value)
    {
        switch (target.Parent)
        {
            case JsonObject o:
                o[target.GetPropertyName()] = value;
                break;
            case JsonArray a:
                a[target.GetElementIndex()] = value;
                break;
        }
    }

    private JsonNode? Nest(JsonNode? value, int depth)
    {
        for (int i = 0; i < depth; i++)
        {
            value = _random.Next(2) == 0 ? new JsonArray(value) : new JsonObject { [RandomName()] = value };
        }
        return value;
    }

    private JsonNode RandomNumber()
    {
        double[] odd = [0, -0.0, 1, -1, 0.5, 1e-320, 1e-9, 1e9, 1e308, -1e308, double.MaxValue, double.Epsilon, 4.2, 0.028575, 3600, 3601, 0.1, 1e-6];
        return _random.Next(3) == 0
            ? JsonValue.Create((_random.NextDouble() * 2 - 1) * Math.Pow(10, _random.Next(-8, 8)))
            : JsonValue.Create(odd[_random.Next(odd.Length)]);
    }

    private JsonNode? RandomValue(int depth) => _random.Next(depth > 1 ? 5 : 8) switch
    {
        0 => null,
        1 => JsonValue.Create(_random.Next(2) == 0),
        2 => RandomNumber(),
        3 => JsonValue.Create(RandomString()),
        4 => JsonValue.Create(_random.Next(-5, 20)),
        5 => new JsonArray(RandomValue(depth + 1), RandomValue(depth + 1)),
        6 => new JsonObject { [RandomName()] = RandomValue(depth + 1) },
        _ => new JsonArray(),
    };

    private string RandomName()
    {
        string[] names = ["format", "name", "table", "physics", "rack", "balls", "shot", "rules", "game", "id", "position", "velocity", "spin", "speed", "aim_deg", "tip", "R", "dt", "model", "integrator", "preset", "seed", "x", "", "ünïcode"];
        return names[_random.Next(names.Length)];
    }

    private string RandomString()
    {
        string[] words = ["", "cue", "8", "16", "standard", "thesis", "exact", "euler", "event", "fixed", "pool-9ft", "pocketless", "eight-ball", "nine-ball", "alciatore", "billiards-scene/1", "NaN", "\u0000", "\ud83c\udfb1", new string('x', 5000)];
        return words[_random.Next(words.Length)];
    }

    private string MutateText(string text)
    {
        if (text.Length == 0)
        {
            return "{";
        }
        int at = _random.Next(text.Length);
        string[] junk = ["NaN", "Infinity", "-Infinity", "1e999", "-1e999", "}", "]", ",", "\"", "\\", "\0", "//c", "/*", "\u00ff", "{\"a\":", "[[[[[[[[", "00", "-", "1.", ".5", "0x10", "true", "null"];
        return _random.Next(5) switch
        {
            0 => text[..at], // truncated
            1 => text[..at] + junk[_random.Next(junk.Length)] + text[at..],
            2 => text.Remove(at, Math.Min(text.Length - at, 1 + _random.Next(10))),
            3 => text.Replace("0.", junk[_random.Next(junk.Length)], StringComparison.Ordinal),
            _ => text[..at] + (char)_random.Next(0x20, 0x7f) + text[at..],
        };
    }

    // ---- command lines ----

    private string[] CommandLineFor(string scene, int index)
    {
        string outFile = Path.Combine(_dir, $"out{index}");
        var args = _random.Next(20) switch
        {
            < 15 => Simulate(scene, outFile),
            < 16 => new List<string> { "render", scene, "--out", outFile + ".png", "--width", "16", "--height", "16", "--at", Pick("0", "0.5", "2") },
            < 17 => new List<string> { "render-audio", scene, "--out", outFile + ".wav" },
            < 18 => ReportLine(scene, outFile),
            _ => new List<string> { Pick("play", "fly", "", "--help-me", "simulate", "report"), scene },
        };
        int mutations = _random.Next(4) == 0 ? 1 + _random.Next(3) : 0;
        for (int m = 0; m < mutations; m++)
        {
            int at = _random.Next(args.Count);
            switch (_random.Next(5))
            {
                case 0:
                    args.RemoveAt(at);
                    break;
                case 1:
                    args.Insert(at, args[_random.Next(args.Count)]);
                    break;
                case 2:
                    args.Insert(at, Pick("--frobnicate", "--out", "--dt", "--until", "--", "-", "--at", "--width", "--model"));
                    break;
                default:
                    args[at] = OddArgument(outFile);
                    break;
            }
        }
        // The game's window must never open (no arguments at all plays the default scene): play
        // is kept only as "play SCENE" with a scene it refuses.
        bool refusedPlay = args.Count == 2 && args[0] == "play" && args[1] == scene && !Loads(scene);
        for (int k = 0; k < args.Count && !refusedPlay; k++)
        {
            if (args[k] == "play")
            {
                args[k] = "fly";
            }
        }
        // Without a verb the root plays the default scene: lead with a verb (or an unknown word).
        if (args.Count == 0 || (!refusedPlay && args[0] is not ("simulate" or "render" or "render-audio" or "report" or "fly")))
        {
            args.Insert(0, "fly");
        }
        return [.. args];
    }

    private List<string> Simulate(string scene, string outFile)
    {
        var args = new List<string> { "simulate", scene };
        if (_random.Next(3) == 0)
        {
            args.AddRange(["--integrator", Pick("exact", "event", "euler", "fixed", "rk4")]);
        }
        if (_random.Next(4) == 0)
        {
            args.AddRange(["--model", Pick("standard", "thesis", "Standard")]);
        }
        if (_random.Next(4) == 0)
        {
            args.AddRange(["--dt", Pick("0.004", "0.1", "0.0333333333", "0.001", "0.2", "0", "1e-7")]);
        }
        if (_random.Next(4) == 0)
        {
            args.AddRange(["--until", Pick("0", "1", "5", "30", "-1", "3601", "1e308", "NaN")]);
        }
        if (_random.Next(6) == 0)
        {
            args.AddRange(["--sample", Pick("0.1", "0.5", "0", "-1", "1e-9")]);
        }
        if (_random.Next(3) == 0)
        {
            args.AddRange(["--out", _random.Next(4) == 0 ? OddArgument(outFile) : outFile + ".json"]);
        }
        // Bound each case's wall clock (a tiny dt over a long time is slow, not wrong).
        args.AddRange(["--max-wall", "0.25"]);
        return args;
    }

    private List<string> ReportLine(string scene, string outFile)
    {
        // A suite of one mutated scene that the loader refuses; a valid one would be measured at
        // length, which the report's own tests cover.
        string suite = Path.Combine(_dir, $"suite{outFile.GetHashCode(StringComparison.Ordinal) & 0xffff}");
        Directory.CreateDirectory(suite);
        File.Copy(scene, Path.Combine(suite, "a.json"), overwrite: true);
        if (Loads(scene))
        {
            File.WriteAllText(Path.Combine(suite, "b.json"), """{ "format": "billiards-scene/1", "balls": [ { "id": "cue", "position": [0, 0] } ] }""");
        }
        return ["report", "accuracy", "--scenes", suite, "--out", _random.Next(2) == 0 ? outFile : OddArgument(outFile)];
    }

    private static bool Loads(string scene)
    {
        try
        {
            SceneLoader.Load(scene);
            return true;
        }
        catch (SceneException)
        {
            return false;
        }
    }

    private string OddArgument(string outFile) => Pick(
        "", " ", ".", "..", "/", _dir, _dir + "/", outFile + "/", outFile + ".png", "/nonexistent/dir/x.json", "-1", "NaN", "1e308", "Infinity",
        "0x10", new string('a', 300), "x\ty", "\u00e9", "--", "-", "--out=", "simulate", "C:\\x", "a\0b");

    private string Pick(params string[] values) => values[_random.Next(values.Length)];
}
