using System.Security.Cryptography;
using System.Text.Json.Nodes;
using Billiards.Core.Scenes;

namespace Billiards.Core.Tests.Physics;

/// <summary>
/// The cross-platform guard beside <see cref="BreakHashTests"/>: shipped scenes run through
/// <c>simulate</c>'s path (<see cref="SceneLoader"/>, <see cref="SimulationRunner"/>,
/// <see cref="ResultWriter"/>), and the SHA-256 of each result, its wall-clock time aside, pinned.
/// The scenes are those whose bits differed between Linux and Windows (wine) while Core took its
/// sines, arc tangents and exponentials from the C runtime: a jump, the Mathavan and
/// stronge-compliant cushions, the thesis engine, a massé and the breaks (docs/determinism.md).
/// The same hashes must come out on every platform; a change of physics that alters them on
/// purpose re-pins them here, in this one table (a failure prints the new value), and says why in
/// its commit message.
/// </summary>
public class ShotHashTests
{
    /// <summary>Scene (under assets/scenes) and the first 16 hex digits of its result's SHA-256.</summary>
    private static readonly Dictionary<string, string> Pinned = new()
    {
        ["eight-ball-break.json"] = "EBF099B49B83D690",
        ["nine-ball-break.json"] = "6F517BA2F2EC9973",
        ["snooker-break.json"] = "392349D914CD8E73",
        ["thesis-nine-ball-break.json"] = "1CCB1B27553C4DCF",
        ["masse.json"] = "3F98074FAA588A83",
        ["draw.json"] = "34856C23D588AD85",
        ["flight/jump.json"] = "16631B7BA3C68C7F",
        ["models/bank-mathavan-2010.json"] = "D6F7088B48B9BC6D",
        ["models/bank-stronge-compliant.json"] = "5CB19ABB9FE2992E",
    };

    public static TheoryData<string> Scenes => new(Pinned.Keys);

    [Theory]
    [MemberData(nameof(Scenes))]
    public void TheShotEndsInThePinnedResult(string file)
    {
        var scene = SceneLoader.Load(AssetFolder.Scene(file), new SceneOverrides(null, null));
        var result = JsonNode.Parse(ResultWriter.ToUtf8(SimulationRunner.Run(scene, new RunOptions())))!;
        result["stats"]!.AsObject().Remove("wall_ms");
        string hash = Convert.ToHexString(SHA256.HashData(System.Text.Encoding.UTF8.GetBytes(result.ToJsonString())))[..16];
        Assert.True(Pinned[file] == hash,
            $"{file}: the result's hash is {hash}, pinned {Pinned[file]}; if the change of bits is meant, pin [\"{file}\"] = \"{hash}\" in ShotHashTests.Pinned");
    }
}
