using System.CommandLine;
using System.Globalization;
using System.Numerics;
using Billiards.App.Rendering;
using Billiards.Core.Scenes;

namespace Billiards.App.Cli;

/// <summary>
/// <c>render SCENE --out FILE.png [--at T] [--width W --height H] [--camera X,Y,Z,TX,TY,TZ[,FOV]] [--model FILE]</c>:
/// draws the scene offscreen (no window; EGL surfaceless when available, else a hidden GLFW
/// window) with the game's renderer and writes a PNG atomically.
/// </summary>
public static class RenderCommand
{
    /// <summary>Largest accepted width or height (pixels).</summary>
    public const int MaxSize = 8192;

    /// <summary>Builds the verb.</summary>
    public static Command Create(TextWriter stdout)
    {
        var scene = new Argument<string>("scene") { Description = "The scene file (billiards-scene/1 JSON)." };
        var output = new Option<string>("--out") { Description = "The PNG file to write.", Required = true };
        var at = new Option<double?>("--at") { Description = "Simulated time (s) to draw; 0 (default) draws the scene as placed, with the cue if it has a shot." };
        var width = new Option<int?>("--width") { Description = "Picture width in pixels (default 1280)." };
        var height = new Option<int?>("--height") { Description = "Picture height in pixels (default 720)." };
        var camera = new Option<string?>("--camera") { Description = "Eye and target in metres, optionally the vertical field of view in degrees: x,y,z,tx,ty,tz[,fov]. Default: behind the head rail, above." };
        var model = new Option<string?>("--model") { Description = "A table model file to load through Assimp instead of the table's own (metres, z up)." };

        var command = new Command("render", VerbHelp.Verb("Draw a scene offscreen into a PNG file.", "render"))
        {
            scene, output, at, width, height, camera, model,
        };
        command.SetAction(parse =>
        {
            string outPath = parse.GetValue(output)!;
            int w = parse.GetValue(width) ?? 1280;
            int h = parse.GetValue(height) ?? 720;
            if (w is < 1 or > MaxSize)
            {
                throw new CliException($"--width {w}: expected 1 to {MaxSize} pixels");
            }
            if (h is < 1 or > MaxSize)
            {
                throw new CliException($"--height {h}: expected 1 to {MaxSize} pixels");
            }
            double time = parse.GetValue(at) ?? 0;
            if (!double.IsFinite(time) || time < 0 || time > RunOptions.MaxUntil)
            {
                throw new CliException(string.Create(CultureInfo.InvariantCulture, $"--at {time}: expected a time from 0 to {RunOptions.MaxUntil} s"));
            }
            (Vector3 Eye, Vector3 Target, float Fov)? cameraValue = parse.GetValue(camera) is { } text ? ParseCamera(text) : null;
            string? modelPath = parse.GetValue(model);
            if (modelPath is not null && !File.Exists(modelPath))
            {
                throw new CliException($"--model {modelPath}: no such file");
            }
            outPath = OutputFiles.Check("--out", outPath, ".png");

            var loaded = SceneLoader.Load(parse.GetValue(scene)!);
            var frame = SceneFrames.Build(loaded, time, w, h);
            if (cameraValue is { } c)
            {
                frame.Eye = c.Eye;
                frame.Target = c.Target;
                frame.FovYDegrees = c.Fov;
            }

            byte[] png;
            try
            {
                using var renderer = new OffscreenRenderer(modelPath is null ? null : _ => Path.GetFullPath(modelPath));
                png = PngEncoder.Encode(renderer.Render(frame), w, h);
            }
            catch (Exception e) when (e is InvalidOperationException or DllNotFoundException or EntryPointNotFoundException)
            {
                throw new EnvironmentException($"render: {e.Message}", e);
            }
            catch (InvalidDataException e)
            {
                throw new CliException($"render: {e.Message}");
            }
            OutputFiles.Write(outPath, png);
            return 0;
        });
        return command;
    }

    /// <summary>Parses <c>x,y,z,tx,ty,tz[,fov]</c> (metres, degrees).</summary>
    public static (Vector3 Eye, Vector3 Target, float Fov) ParseCamera(string text)
    {
        string[] parts = text.Split(',', StringSplitOptions.TrimEntries);
        var values = new float[parts.Length];
        for (int i = 0; i < parts.Length; i++)
        {
            if (!float.TryParse(parts[i], NumberStyles.Float, CultureInfo.InvariantCulture, out values[i]) || !float.IsFinite(values[i]))
            {
                throw new CliException($"--camera {text}: '{parts[i]}' is not a number (expected x,y,z,tx,ty,tz[,fov] in metres and degrees)");
            }
        }
        if (values.Length is not (6 or 7))
        {
            throw new CliException($"--camera {text}: expected 6 or 7 numbers x,y,z,tx,ty,tz[,fov], got {values.Length}");
        }
        var eye = new Vector3(values[0], values[1], values[2]);
        var target = new Vector3(values[3], values[4], values[5]);
        if (Vector3.Distance(eye, target) < 1e-4f)
        {
            throw new CliException($"--camera {text}: the eye and the target are the same point");
        }
        float fov = values.Length == 7 ? values[6] : 45;
        if (fov is <= 1 or >= 179)
        {
            throw new CliException($"--camera {text}: field of view {fov} deg; expected 1 to 179");
        }
        return (eye, target, fov);
    }
}
