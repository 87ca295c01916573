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
        ["eight-ball-break.json"] = "1AB5B91F5D7BAA4F",
        ["nine-ball-break.json"] = "5AC479A285760CE1",
        ["snooker-break.json"] = "21E65E57D0DE7832",
        ["thesis-nine-ball-break.json"] = "19EEC06CACBE73B6",
        ["masse.json"] = "A2DEC68F3133350F",
        ["draw.json"] = "EED71DB812A3EF9E",
        ["flight/jump.json"] = "2A295F2A0A572EC4",
        ["models/bank-mathavan-2010.json"] = "145A911DF85658C8",
        ["models/bank-stronge-compliant.json"] = "CF0CD998262C998B",
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
