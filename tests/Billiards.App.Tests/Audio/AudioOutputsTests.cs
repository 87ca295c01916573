using Billiards.App.Audio;

namespace Billiards.App.Tests.Audio;

public sealed class AudioOutputsTests
{
    [Fact]
    public void WithoutTheOpenAlLibraryTheGameIsSilentAndSaysSoInOneLine()
    {
        var stderr = new StringWriter();
        using var output = AudioOutputs.Open(stderr, libraries: ["libno-such-openal.so.9"]);
        Assert.True(output.IsSilent);
        string line = Assert.Single(stderr.ToString().TrimEnd('\n').Split('\n'));
        Assert.Contains("OpenAL Soft not found", line);
        Assert.EndsWith("playing without sound", line);
        // Silence still takes every call.
        output.Play(new SoundCue(0, SoundKind.BallClick, 1, default, false, 0));
        output.SetRolling(0, 1, default);
    }

    [Fact]
    public void WhenNoDeviceOpensTheGameIsSilentAndSaysSoInOneLine()
    {
        var stderr = new StringWriter();
        using var output = AudioOutputs.Open(stderr, deviceName: "no such audio device 7f3a");
        Assert.True(output.IsSilent);
        string line = Assert.Single(stderr.ToString().TrimEnd('\n').Split('\n'));
        // With OpenAL Soft installed the device is refused by name; without it, the library is missing.
        Assert.True(line.Contains("no audio device \"no such audio device 7f3a\"", StringComparison.Ordinal) || line.Contains("OpenAL Soft not found", StringComparison.Ordinal), line);
        Assert.EndsWith("playing without sound", line);
    }
}
