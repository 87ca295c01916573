using Billiards.App.Cli;
using Billiards.Core.Practice;
using Billiards.Core.Scenes;

namespace Billiards.App.Practice;

/// <summary>The shipped drills: <c>assets/drills/*.json</c> beside the executable, by name.</summary>
public static class DrillLibrary
{
    /// <summary>The drills folder.</summary>
    public static string Folder => Path.Combine(AssetFolder.Assets, "drills");

    /// <summary>Every shipped drill's name, sorted.</summary>
    public static IReadOnlyList<string> Names() =>
        Directory.Exists(Folder)
            ? [.. Directory.EnumerateFiles(Folder, "*.json").Select(f => Path.GetFileNameWithoutExtension(f)).Order(StringComparer.Ordinal)]
            : [];

    /// <summary>Every shipped drill, in name order.</summary>
    public static IReadOnlyList<Drill> All() => [.. Names().Select(Load)];

    /// <summary>
    /// A drill by its name (a shipped drill) or by a path to a drill file; an unknown name or a bad
    /// file is a <see cref="CliException"/> or <see cref="SceneException"/> of one line.
    /// </summary>
    public static Drill Load(string nameOrPath)
    {
        ArgumentNullException.ThrowIfNull(nameOrPath);
        string path = nameOrPath.EndsWith(".json", StringComparison.OrdinalIgnoreCase) ? nameOrPath : Path.Combine(Folder, nameOrPath + ".json");
        if (!File.Exists(path))
        {
            throw new CliException($"--drill {nameOrPath}: no such drill (the drills are {string.Join(", ", Names())}; or give a drill file's path)");
        }
        string text;
        try
        {
            text = File.ReadAllText(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new CliException($"--drill {nameOrPath}: cannot read {path} ({e.Message})");
        }
        return Drill.Parse(text, path);
    }
}
