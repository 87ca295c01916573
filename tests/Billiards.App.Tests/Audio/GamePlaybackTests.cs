using System.Diagnostics;
using System.Text.RegularExpressions;
using Billiards.App.Tests.Rendering;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Audio;

/// <summary>
/// The game really plays sound through OpenAL Soft: the game runs in its own process with OpenAL
/// Soft's wave writer as the device (no sound card needed), and the mix it wrote is checked.
/// </summary>
[Collection("GL")]
public sealed partial class GamePlaybackTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("billiards-playback-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    [Fact]
    public void TheGamePlaysTheBreakThroughOpenAlSoft()
    {
        if (!OperatingSystem.IsLinux() || !File.Exists("/usr/lib/x86_64-linux-gnu/libopenal.so.1") && !File.Exists("/usr/lib/aarch64-linux-gnu/libopenal.so.1"))
        {
            // Only where Debian's libopenal1 is installed (.ci/run installs it).
            return;
        }
        TestDisplay.Ensure();
        string wav = Path.Combine(_dir, "mix.wav");
        string conf = Path.Combine(_dir, "alsoft.conf");
        File.WriteAllText(conf, $"[general]\ndrivers=wave\n[wave]\nfile={wav}\n");
        var start = new ProcessStartInfo("dotnet") { RedirectStandardError = true, UseShellExecute = false };
        start.ArgumentList.Add(Path.Combine(AppContext.BaseDirectory, "billiards.dll"));
        start.ArgumentList.Add("play");
        start.ArgumentList.Add(AssetFolder.Scene("eight-ball-break.json"));
        // The script closes the game after its 4 s; the scene breaks as the game starts.
        start.ArgumentList.Add("--script");
        start.ArgumentList.Add(Path.Combine(AssetFolder.Assets, "scripts", "break-short.json"));
        start.Environment["ALSOFT_DRIVERS"] = "wave";
        start.Environment["ALSOFT_CONF"] = conf;
        start.Environment["BILLIARDS_AUDIO_STATS"] = "1";
        using var process = Process.Start(start)!;
        string stderr = process.StandardError.ReadToEnd();
        Assert.True(process.WaitForExit(120_000), "the game did not close after its script");
        Assert.True(process.ExitCode == 0, stderr);
        Assert.DoesNotContain("playing without sound", stderr);

        // The player's own count: the break's sounds went to the device.
        var stats = StatsLine().Match(stderr);
        Assert.True(stats.Success, stderr);
        Assert.True(int.Parse(stats.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture) >= 20, stats.Value);

        // And OpenAL Soft mixed them into the file: 32-bit float stereo, with the break's clicks in it.
        float[] mix = ReadFloatWav(wav);
        float peak = mix.Max(Math.Abs);
        Assert.True(peak > 0.05f, $"the written mix peaks at {peak}");
    }

    [GeneratedRegex(@"audio on .*: (\d+) sounds")]
    private static partial Regex StatsLine();

    // OpenAL Soft's wave writer: WAVE_FORMAT_EXTENSIBLE, IEEE float, so read its data chunk directly.
    private static float[] ReadFloatWav(string path)
    {
        byte[] bytes = File.ReadAllBytes(path);
        int i = 12;
        while (i + 8 <= bytes.Length)
        {
            string id = System.Text.Encoding.ASCII.GetString(bytes, i, 4);
            int size = BitConverter.ToInt32(bytes, i + 4);
            if (id == "data")
            {
                // A writer stopped early may leave the size unset: take what is there.
                int length = size > 0 && i + 8 + size <= bytes.Length ? size : bytes.Length - i - 8;
                var samples = new float[length / 4];
                Buffer.BlockCopy(bytes, i + 8, samples, 0, samples.Length * 4);
                return samples;
            }
            i += 8 + size;
        }
        throw new InvalidDataException($"{path}: no data chunk");
    }
}
