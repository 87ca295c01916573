using Billiards.App.Cli;

namespace Billiards.App.Tests.Cli;

public sealed class SimulateCommandErrorTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("billiards-cli-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private static (int Code, string Out, string Err) Run(params string[] args) => CliRun.Run(args);

    private string Write(string name, string json)
    {
        string path = Path.Combine(_dir, name);
        File.WriteAllText(path, json);
        return path;
    }

    private static void AssertOneLine(string err)
    {
        string[] lines = err.TrimEnd('\n').Split('\n');
        Assert.Single(lines);
        Assert.DoesNotContain("   at ", err); // no stack trace
    }

    [Fact]
    public void AMalformedSceneExitsNonZeroWithOneLineNamingFilePathAndProblemAndWritesNothing()
    {
        string scene = Write("bad.json", """{ "format": "billiards-scene/1", "balls": [ { "id": "cue", "position": [0, "x"] } ] }""");
        string output = Path.Combine(_dir, "result.json");
        var (code, stdout, stderr) = Run("simulate", scene, "--out", output);
        Assert.Equal(CommandLine.BadInput, code);
        Assert.Equal("", stdout);
        AssertOneLine(stderr);
        Assert.Equal($"{scene}: $.balls[0].position[1]: expected a number, found the string \"x\"", stderr.TrimEnd('\n'));
        Assert.False(File.Exists(output));
        Assert.Empty(Directory.GetFiles(_dir, "result.json*"));
    }

    [Fact]
    public void AMissingSceneFileIsOneLine()
    {
        var (code, _, stderr) = Run("simulate", Path.Combine(_dir, "missing.json"));
        Assert.Equal(CommandLine.BadInput, code);
        AssertOneLine(stderr);
        Assert.Contains("missing.json: $: cannot read the file", stderr);
    }

    [Theory]
    [InlineData("simulate")]                                  // no scene
    [InlineData("simulate", "a.json", "--dt", "fast")]       // not a number
    [InlineData("simulate", "a.json", "--frobnicate")]       // unknown option
    [InlineData("fly")]                                       // unknown verb
    public void BadArgumentsAreOneLineAndNonZero(params string[] args)
    {
        var (code, stdout, stderr) = Run(args);
        Assert.NotEqual(0, code);
        Assert.Equal("", stdout);
        AssertOneLine(stderr);
        Assert.StartsWith("billiards: ", stderr);
    }

    [Theory]
    [InlineData("--until", "-1", "--until -1: expected a time from 0 to 3600 s")]
    [InlineData("--until", "1e308", "--until 1E+308: expected a time from 0 to 3600 s")]
    [InlineData("--sample", "0", "--sample 0: expected a positive interval (s)")]
    [InlineData("--dt", "5", "--dt: $: dt 5 is out of range")]
    [InlineData("--integrator", "rk4", "--integrator: $: integrator \"rk4\" is not available for model \"standard\"")]
    public void OutOfRangeOptionsAreOneLineAndNonZero(string option, string value, string expected)
    {
        string scene = Write("ok.json", """{ "format": "billiards-scene/1", "balls": [ { "id": "cue", "position": [0, 0] } ] }""");
        var (code, stdout, stderr) = Run("simulate", scene, option, value);
        Assert.Equal(CommandLine.BadInput, code);
        Assert.Equal("", stdout);
        AssertOneLine(stderr);
        Assert.Contains(expected, stderr);
    }
}
