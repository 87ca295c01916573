using System.Text.Json;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Collisions;
using Billiards.Core.Scenes;

namespace Billiards.App.Game;

/// <summary>
/// The player's physics choice of the start menu, kept between runs in <c>settings.json</c> under
/// the user's configuration folder ($XDG_CONFIG_HOME/billiards, else ~/.config/billiards; the
/// platform's application data folder elsewhere): the cushion model and the cloth, how fast
/// the computer plays, whether the players allow take-backs, the sound, the graphics, and the last
/// game and opponent chosen.
/// </summary>
/// <param name="Cushion">A cushion model of <see cref="ModelRegistry.BallCushionModels"/>.</param>
/// <param name="Cloth">A cloth of <see cref="Core.Physics.Cloth.All"/>.</param>
/// <param name="FastComputer">The computer turns and strikes fast (<see cref="ComputerPlayerNode.Fast"/>), not at a pace one can watch.</param>
/// <param name="TakeBacks">The players allow take-backs in a game (off by default; practice always allows them).</param>
public sealed record GameSettings(IBallCushionModel Cushion, Cloth Cloth, bool FastComputer = false, bool TakeBacks = false)
{
    /// <summary>The game the start menu's Play screen offers first: the last one started (8-ball at first).</summary>
    public Billiards.Core.Rules.GameRules Game { get; init; } = Billiards.Core.Rules.GameRules.EightBall;

    /// <summary>The opponent the Play screen offers first: a computer level 1-5, or null for a person (level 3 at first).</summary>
    public int? Opponent { get; init; } = 3;

    /// <summary>The sound is muted (U in the game).</summary>
    public bool Muted { get; init; }

    /// <summary>How the 3D scene is drawn while the view moves (<see cref="GraphicsQuality"/>; automatic at first).</summary>
    public GraphicsQuality Graphics { get; init; }

    /// <summary>The physics alone, which makes the game: the other settings (pace, take-backs, sound, the menu's last choices) do not change it.</summary>
    public GameSettings Physics => new(Cushion, Cloth);

    /// <summary>The model's defaults.</summary>
    public static GameSettings Default { get; } = new(InteractionModels.Default.BallCushion, Cloth.Standard);

    /// <summary>The settings file of this user.</summary>
    public static string DefaultPath(Func<string, string?>? environment = null)
    {
        environment ??= Environment.GetEnvironmentVariable;
        string? config = environment("XDG_CONFIG_HOME");
        if (string.IsNullOrEmpty(config))
        {
            string home = environment("HOME") is { Length: > 0 } h ? h : Environment.GetFolderPath(Environment.SpecialFolder.UserProfile);
            config = OperatingSystem.IsWindows() ? Environment.GetFolderPath(Environment.SpecialFolder.ApplicationData) : Path.Combine(home, ".config");
        }
        return Path.Combine(config, "billiards", "settings.json");
    }

    /// <summary>
    /// The scene with this physics, for a model that takes it (the standard model); other scenes as
    /// they are. The standard cloth leaves a ball set's own cloth (carom's heated cloth) in place.
    /// </summary>
    public Scene Apply(Scene scene)
    {
        ArgumentNullException.ThrowIfNull(scene);
        var physics = scene.Physics;
        if (!physics.Model.TakesInteractionModels)
        {
            return scene;
        }
        var cloth = Cloth == Cloth.Standard && scene.BallSet.Cloth is { } own ? own : Cloth;
        return scene with { Physics = physics with { Models = physics.Models with { BallCushion = Cushion }, Params = cloth.On(physics.Params) } };
    }

    /// <summary>
    /// The settings in <paramref name="path"/>; the defaults when there is no file, and for a file
    /// that cannot be read or names what this version does not know (one line on
    /// <paramref name="warnings"/>: a broken settings file never stops the game).
    /// </summary>
    public static GameSettings Load(string path, TextWriter? warnings = null)
    {
        if (!File.Exists(path))
        {
            return Default;
        }
        try
        {
            using var doc = JsonDocument.Parse(File.ReadAllText(path));
            var root = doc.RootElement;
            string? cushion = root.TryGetProperty("ball_cushion", out var c) && c.ValueKind == JsonValueKind.String ? c.GetString() : null;
            string? cloth = root.TryGetProperty("cloth", out var k) && k.ValueKind == JsonValueKind.String ? k.GetString() : null;
            // A file from before the pace was kept says nothing of it: the watchable pace.
            bool fast = root.TryGetProperty("computer_pace", out var p) && p.ValueKind == JsonValueKind.String && p.GetString() == "fast";
            // A file from before take-backs has none: off, the default.
            bool takeBacks = root.TryGetProperty("take_backs", out var t) && t.ValueKind == JsonValueKind.True;
            bool muted = root.TryGetProperty("sound", out var m) && m.ValueKind == JsonValueKind.String && m.GetString() == "muted";
            // A file from before the graphics setting, or one naming an unknown value: automatic.
            var graphics = root.TryGetProperty("graphics", out var q) && q.ValueKind == JsonValueKind.String ? GraphicsWords.Parse(q.GetString()) : GraphicsQuality.Auto;
            // The last game and opponent: a file from before them, or one naming an unknown game, offers 8-ball against level 3.
            var game = root.TryGetProperty("game", out var g) && g.ValueKind == JsonValueKind.String && Billiards.Core.Rules.RuleNames.TryParseGame(g.GetString(), out var parsed) ? parsed : Billiards.Core.Rules.GameRules.EightBall;
            int? opponent = !root.TryGetProperty("opponent", out var o) ? 3
                : o.ValueKind == JsonValueKind.Number && o.TryGetInt32(out int level) && level is >= 1 and <= 5 ? level
                : o.ValueKind == JsonValueKind.String && o.GetString() == "person" ? null : 3;
            if (ModelRegistry.FindBallCushion(cushion) is { } model && Cloth.Find(cloth) is { } found)
            {
                return new GameSettings(model, found, fast, takeBacks) { Game = game, Opponent = opponent, Muted = muted, Graphics = graphics };
            }
            warnings?.WriteLine($"billiards: {path}: unknown cushion model or cloth; using the defaults");
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or JsonException or InvalidOperationException)
        {
            warnings?.WriteLine($"billiards: {path}: cannot read the settings ({e.Message}); using the defaults");
        }
        return Default;
    }

    /// <summary>Writes the settings to <paramref name="path"/> (creating its folder); a failure is one line on <paramref name="warnings"/>.</summary>
    public void Save(string path, TextWriter? warnings = null)
    {
        try
        {
            Directory.CreateDirectory(Path.GetDirectoryName(Path.GetFullPath(path))!);
            using var stream = new MemoryStream();
            using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true }))
            {
                w.WriteStartObject();
                w.WriteString("ball_cushion", Cushion.Name);
                w.WriteString("cloth", Cloth.Name);
                w.WriteString("computer_pace", FastComputer ? "fast" : "watchable");
                w.WriteBoolean("take_backs", TakeBacks);
                w.WriteString("sound", Muted ? "muted" : "on");
                w.WriteString("graphics", GraphicsWords.Name(Graphics));
                w.WriteString("game", Billiards.Core.Rules.RuleNames.ToName(Game));
                if (Opponent is int level)
                {
                    w.WriteNumber("opponent", level);
                }
                else
                {
                    w.WriteString("opponent", "person");
                }
                w.WriteEndObject();
            }
            File.WriteAllBytes(path, stream.ToArray());
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            warnings?.WriteLine($"billiards: {path}: cannot save the settings ({e.Message})");
        }
    }
}

/// <summary>How the 3D scene is drawn while the view moves (the Settings screen's Graphics line).</summary>
public enum GraphicsQuality
{
    /// <summary>Full resolution on a graphics card; on a software rasteriser a moving view is drawn at reduced resolution and sharpened when it stops.</summary>
    Auto,

    /// <summary>Always full resolution, moving or not (smooth only on a fast renderer).</summary>
    Sharp,

    /// <summary>A moving view at reduced resolution on any renderer, sharp again as soon as it stands still.</summary>
    Fast,
}

/// <summary>The names of <see cref="GraphicsQuality"/> in the settings file and in words on the Settings screen.</summary>
public static class GraphicsWords
{
    /// <summary>The settings file's name: auto, sharp or fast.</summary>
    public static string Name(GraphicsQuality quality) => quality switch
    {
        GraphicsQuality.Sharp => "sharp",
        GraphicsQuality.Fast => "fast",
        _ => "auto",
    };

    /// <summary>The quality a settings file names; automatic for anything else.</summary>
    public static GraphicsQuality Parse(string? name) => name switch
    {
        "sharp" => GraphicsQuality.Sharp,
        "fast" => GraphicsQuality.Fast,
        _ => GraphicsQuality.Auto,
    };

    /// <summary>The Settings screen's words.</summary>
    public static string Words(GraphicsQuality quality) => quality switch
    {
        GraphicsQuality.Sharp => "always sharp",
        GraphicsQuality.Fast => "fast (softer while the view moves)",
        _ => "automatic",
    };

    /// <summary>Whether a moving view is drawn at reduced resolution, on a software rasteriser or not.</summary>
    public static bool ReducesWhileMoving(GraphicsQuality quality, bool softwareRenderer) =>
        quality == GraphicsQuality.Fast || (quality == GraphicsQuality.Auto && softwareRenderer);
}
