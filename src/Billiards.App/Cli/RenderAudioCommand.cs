using System.CommandLine;
using Billiards.App.Audio;
using Billiards.Core.Scenes;

namespace Billiards.App.Cli;

/// <summary>
/// <c>render-audio SCENE --out FILE.wav [--rate 48000]</c>: the sound of the scene's shot,
/// offline, with the game's synthesis (<see cref="ShotAudio"/>), written atomically as 16-bit
/// stereo PCM. Deterministic bit for bit; never opens an audio device.
/// </summary>
public static class RenderAudioCommand
{
    /// <summary>Default sample rate (Hz).</summary>
    public const int DefaultRate = 48000;

    /// <summary>Lowest and highest accepted sample rates (Hz).</summary>
    public const int MinRate = 8000, MaxRate = 192000;

    /// <summary>Builds the verb.</summary>
    public static Command Create()
    {
        var scene = new Argument<string>("scene") { Description = "The scene file (billiards-scene/1 JSON)." };
        var output = new Option<string>("--out") { Description = "The WAV file to write.", Required = true };
        var rate = new Option<int?>("--rate") { Description = $"Sample rate in Hz (default {DefaultRate})." };
        var command = new Command("render-audio", VerbHelp.Verb("Render the sound of a scene's shot into a WAV file.", "render-audio")) { scene, output, rate };
        command.SetAction(parse =>
        {
            string outPath = parse.GetValue(output)!;
            int sampleRate = parse.GetValue(rate) ?? DefaultRate;
            if (sampleRate is < MinRate or > MaxRate)
            {
                throw new CliException($"--rate {sampleRate}: expected {MinRate} to {MaxRate} Hz");
            }
            outPath = OutputFiles.Check("--out", outPath, ".wav");
            var loaded = SceneLoader.Load(parse.GetValue(scene)!);
            float[] samples = ShotAudio.Render(loaded, sampleRate);
            OutputFiles.Write(outPath, WavFile.Encode(samples, sampleRate, 2));
            return 0;
        });
        return command;
    }
}
