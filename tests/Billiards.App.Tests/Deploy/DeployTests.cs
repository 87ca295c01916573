using System.Diagnostics;
using System.Text.RegularExpressions;
using System.Xml.Linq;
using Billiards.App.Cli;
using Billiards.App.Tests.Cli;
using YamlDotNet.RepresentationModel;

namespace Billiards.App.Tests.Deploy;

/// <summary>
/// deploy/: the Kubernetes manifests (read as YAML), the Dockerfile (its stages and the paths it
/// names) and deploy/run-local.sh, which runs the manifests' own commands as local processes. No
/// cluster and no Docker engine are reachable here: what can be checked without them is.
/// </summary>
public sealed partial class DeployTests : IDisposable
{
    private static readonly string s_root = FindRoot();
    private static readonly string s_kube = Path.Combine(s_root, "deploy", "kubernetes");
    private readonly string _dir = Directory.CreateTempSubdirectory("billiards-deploy-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private static string FindRoot()
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            if (File.Exists(Path.Combine(dir.FullName, "Billiards.sln")))
            {
                return dir.FullName;
            }
        }
        throw new InvalidOperationException("the repository (Billiards.sln) is not above the test assembly");
    }

    private static List<YamlMappingNode> Documents(string file)
    {
        var stream = new YamlStream();
        using (var reader = new StreamReader(Path.Combine(s_kube, file)))
        {
            stream.Load(reader);
        }
        return [.. stream.Documents.Select(d => (YamlMappingNode)d.RootNode)];
    }

    private static YamlNode At(YamlNode node, params string[] path)
    {
        foreach (string key in path)
        {
            node = ((YamlMappingNode)node).Children[new YamlScalarNode(key)];
        }
        return node;
    }

    private static string Text(YamlNode node, params string[] path) => ((YamlScalarNode)At(node, path)).Value!;

    private static YamlMappingNode Job(string file) => Documents(file).Single(d => Text(d, "kind") == "Job");

    private static YamlMappingNode Container(YamlMappingNode job) => (YamlMappingNode)((YamlSequenceNode)At(job, "spec", "template", "spec", "containers")).Single();

    private static Dictionary<string, string> Env(YamlMappingNode container) =>
        ((YamlSequenceNode)At(container, "env")).Cast<YamlMappingNode>().ToDictionary(e => Text(e, "name"), e => Text(e, "value"));

    // The pod's shell script: command /bin/sh -c, the script its one argument.
    private static string Script(YamlMappingNode container)
    {
        Assert.Equal(["/bin/sh", "-c"], ((YamlSequenceNode)At(container, "command")).Select(n => ((YamlScalarNode)n).Value));
        return ((YamlScalarNode)((YamlSequenceNode)At(container, "args")).Single()).Value!;
    }

    [GeneratedRegex(@"\$\{?([A-Z_][A-Z0-9_]*)")]
    private static partial Regex Variable();

    [GeneratedRegex(@"(?<=\s)--[a-z-]+")]
    private static partial Regex Option();

    // Every option the script gives billiards selfplay is one of the verb's.
    private static void OptionsAreTheVerbs(string script)
    {
        var verb = SelfplayCommand.Create(TextWriter.Null, TextWriter.Null);
        var known = verb.Options.Select(o => o.Name).ToHashSet();
        var used = Option().Matches(script).Select(m => m.Value).ToList();
        Assert.NotEmpty(used);
        Assert.All(used, o => Assert.Contains(o, known));
    }

    [Fact]
    public void TheShardJobIsIndexedAndEachPodRunsItsShardIntoTheSharedVolume()
    {
        var docs = Documents("selfplay-job.yaml");
        var job = Job("selfplay-job.yaml");
        Assert.Equal("batch/v1", Text(job, "apiVersion"));
        Assert.Equal("Indexed", Text(job, "spec", "completionMode"));
        int completions = int.Parse(Text(job, "spec", "completions"), System.Globalization.CultureInfo.InvariantCulture);
        Assert.InRange(int.Parse(Text(job, "spec", "parallelism"), System.Globalization.CultureInfo.InvariantCulture), 1, completions);
        Assert.Equal("Never", Text(job, "spec", "template", "spec", "restartPolicy"));

        var container = Container(job);
        var env = Env(container);
        Assert.Equal(completions.ToString(System.Globalization.CultureInfo.InvariantCulture), env["N"]);
        Assert.Equal(["N", "RULES", "GAMES", "LEVELS", "SEED", "DATA"], env.Keys);
        string script = Script(container);
        Assert.Contains("billiards selfplay ", script, StringComparison.Ordinal);
        Assert.Contains("--shard \"$JOB_COMPLETION_INDEX/$N\"", script, StringComparison.Ordinal);
        Assert.Contains("--summary \"$DATA/summary-$JOB_COMPLETION_INDEX.json\"", script, StringComparison.Ordinal);
        Assert.Contains("--out \"$DATA/games-$JOB_COMPLETION_INDEX.jsonl\"", script, StringComparison.Ordinal);
        // Every variable is the manifest's or the one Kubernetes sets for an Indexed Job.
        Assert.All(Variable().Matches(script).Select(m => m.Groups[1].Value), v => Assert.True(v == "JOB_COMPLETION_INDEX" || env.ContainsKey(v), v));
        OptionsAreTheVerbs(script);
        // A pod searches on as many threads as the cores it requests (the default would be
        // every core of the node it lands on).
        var threads = System.Text.RegularExpressions.Regex.Match(script, @"--threads (\d+)");
        Assert.True(threads.Success, script);
        Assert.Equal(Text(container, "resources", "requests", "cpu"), threads.Groups[1].Value);
        // The values are a run the verb accepts (the one the README measures).
        Assert.Equal("eight-ball", env["RULES"]);
        Assert.Equal(new Core.Rules.PerPlayer<int>(3, 3), SelfplayCommand.ParseLevels(env["LEVELS"]));

        // DATA is where the shared volume is mounted, a claim every pod can write at once.
        var mount = (YamlMappingNode)((YamlSequenceNode)At(container, "volumeMounts")).Single();
        Assert.Equal(env["DATA"], Text(mount, "mountPath"));
        var volume = (YamlMappingNode)((YamlSequenceNode)At(job, "spec", "template", "spec", "volumes")).Single();
        Assert.Equal(Text(mount, "name"), Text(volume, "name"));
        string claim = Text(volume, "persistentVolumeClaim", "claimName");
        var pvc = docs.Single(d => Text(d, "kind") == "PersistentVolumeClaim");
        Assert.Equal(claim, Text(pvc, "metadata", "name"));
        Assert.Equal("ReadWriteMany", ((YamlScalarNode)((YamlSequenceNode)At(pvc, "spec", "accessModes")).Single()).Value);
    }

    [Fact]
    public void TheMergeJobMergesTheSameShardsFromTheSameVolume()
    {
        var shards = Container(Job("selfplay-job.yaml"));
        var merge = Container(Job("merge-job.yaml"));
        var env = Env(merge);
        Assert.Equal(Env(shards)["N"], env["N"]);
        Assert.Equal(Env(shards)["DATA"], env["DATA"]);
        Assert.Equal(Text(shards, "image"), Text(merge, "image"));
        string script = Script(merge);
        Assert.Contains("billiards selfplay --merge $summaries --summary \"$DATA/summary.json\"", script, StringComparison.Ordinal);
        Assert.Contains("summary-$i.json", script, StringComparison.Ordinal);
        Assert.Contains("games-$i.jsonl", script, StringComparison.Ordinal);
        Assert.All(Variable().Matches(script).Select(m => m.Groups[1].Value), v => Assert.True(env.ContainsKey(v) || v is "i" or "summaries" or "records", v));
        OptionsAreTheVerbs(script);
        var claims = new[] { "selfplay-job.yaml", "merge-job.yaml" }
            .Select(f => Text(((YamlSequenceNode)At(Job(f), "spec", "template", "spec", "volumes")).Single(), "persistentVolumeClaim", "claimName"));
        Assert.Single(claims.Distinct());
    }

    [Fact]
    public void TheImageTagIsTheRepositorysVersion()
    {
        var props = XDocument.Load(Path.Combine(s_root, "Directory.Build.props"));
        string version = props.Descendants("Version").Single().Value;
        Assert.Equal($"billiards:{version}", Text(Container(Job("selfplay-job.yaml")), "image"));
        Assert.Contains($"-t billiards:{version} .", File.ReadAllText(Path.Combine(s_kube, "Dockerfile")), StringComparison.Ordinal);
    }

    private sealed record Stage(string Name, string From, List<string> Lines);

    private static List<Stage> Stages()
    {
        var stages = new List<Stage>();
        string pending = "";
        foreach (string raw in File.ReadAllLines(Path.Combine(s_kube, "Dockerfile")))
        {
            if (raw.TrimStart().StartsWith('#') || raw.Trim().Length == 0)
            {
                continue;
            }
            // Continuation lines make one instruction.
            pending += raw.TrimEnd('\\').Trim() + " ";
            if (raw.EndsWith('\\'))
            {
                continue;
            }
            string line = pending.Trim();
            pending = "";
            var from = FromLine().Match(line);
            if (from.Success)
            {
                stages.Add(new Stage(from.Groups[2].Value, from.Groups[1].Value, []));
            }
            else
            {
                stages[^1].Lines.Add(line);
            }
        }
        return stages;
    }

    [GeneratedRegex(@"^FROM (\S+) AS (\S+)$")]
    private static partial Regex FromLine();

    [Fact]
    public void TheDockerfileBuildsWithTheSdkAndRunsOnTheRuntimeWithNativeLibrariesOnlyForRendering()
    {
        var stages = Stages();
        Assert.Equal(["build", "headless", "render"], stages.Select(s => s.Name));
        // The SDK and runtime of the repository's .NET (global.json's SDK band, the projects' target).
        string sdk = File.ReadAllText(Path.Combine(s_root, "global.json"));
        string major = Regex.Match(sdk, "\"version\": \"(\\d+)\\.").Groups[1].Value;
        string framework = XDocument.Load(Path.Combine(s_root, "Directory.Build.props")).Descendants("TargetFramework").Single().Value;
        Assert.Equal($"net{major}.0", framework);
        Assert.Equal($"mcr.microsoft.com/dotnet/sdk:{major}.0", stages[0].From);
        Assert.Equal($"mcr.microsoft.com/dotnet/runtime:{major}.0", stages[1].From);
        Assert.Equal("headless", stages[2].From);

        // Every path the build stage copies or builds exists in the repository.
        var build = stages[0].Lines;
        var copied = build.Where(l => l.StartsWith("COPY ", StringComparison.Ordinal))
            .SelectMany(l => l.Split(' ', StringSplitOptions.RemoveEmptyEntries)[1..^1]).ToList();
        Assert.Contains("src/", copied);
        Assert.Contains("assets/", copied);
        Assert.All(copied, p => Assert.True(File.Exists(Path.Combine(s_root, p)) || Directory.Exists(Path.Combine(s_root, p)), p));
        var projects = build.SelectMany(l => l.Split(' ')).Where(w => w.EndsWith(".csproj", StringComparison.Ordinal)).ToList();
        Assert.Contains("src/Billiards.App/Billiards.App.csproj", projects);
        Assert.All(projects, p => Assert.True(File.Exists(Path.Combine(s_root, p)), p));
        Assert.Contains(build, l => l.StartsWith("RUN dotnet publish src/Billiards.App/Billiards.App.csproj -c Release", StringComparison.Ordinal) && l.EndsWith("-o /app", StringComparison.Ordinal));
        // Every project the App references is copied before the restore.
        string app = Path.Combine(s_root, "src", "Billiards.App");
        foreach (var reference in XDocument.Load(Path.Combine(app, "Billiards.App.csproj")).Descendants("ProjectReference"))
        {
            string path = Path.GetRelativePath(s_root, Path.GetFullPath(Path.Combine(app, reference.Attribute("Include")!.Value))).Replace('\\', '/');
            Assert.Contains(path, copied);
        }

        // The headless image is the published App on the runtime and nothing else; its command is billiards.
        var headless = stages[1].Lines;
        Assert.Contains("COPY --from=build /app ./", headless);
        Assert.DoesNotContain(headless, l => l.Contains("apt-get", StringComparison.Ordinal));
        string assembly = XDocument.Load(Path.Combine(s_root, "src/Billiards.App/Billiards.App.csproj")).Descendants("AssemblyName").Single().Value;
        Assert.Contains($"RUN ln -s /app/{assembly} /usr/local/bin/billiards", headless);
        Assert.Contains("ENTRYPOINT [\"billiards\"]", headless);
        Assert.Contains("USER app", headless);

        // Rendering adds the libraries the README names for offscreen render, no window and no sound.
        string install = Assert.Single(stages[2].Lines, l => l.Contains("apt-get install", StringComparison.Ordinal));
        var packages = install.Split(' ').SkipWhile(w => w != "--no-install-recommends").Skip(1).TakeWhile(w => w != "&&").ToList();
        string readme = File.ReadAllText(Path.Combine(s_root, "README.md"));
        string linux = Regex.Match(readme, "`apt-get install (libglfw3[^`]*)`").Groups[1].Value;
        Assert.NotEmpty(packages);
        Assert.All(packages, p => Assert.Contains(p, linux.Split(' ')));
        Assert.DoesNotContain("libglfw3", packages);
        Assert.DoesNotContain("libopenal1", packages);

        // The build context leaves out build outputs but never what the image copies.
        string[] ignored = [.. File.ReadAllLines(Path.Combine(s_kube, "Dockerfile.dockerignore")).Where(l => l.Length > 0 && !l.StartsWith('#'))];
        Assert.Contains("**/bin/", ignored);
        Assert.All(copied, p => Assert.DoesNotContain(p, ignored));
    }

    [Fact]
    public async Task RunLocalRunsTheManifestsPodsAndGivesTheUnshardedRunsSummaryAndRecords()
    {
        string data = Path.Combine(_dir, "volume");
        var start = new ProcessStartInfo("bash") { RedirectStandardOutput = true, RedirectStandardError = true };
        foreach (string a in new[] { Path.Combine(s_root, "deploy", "run-local.sh"), "--indexes", "3", "--data", data, "--set", "GAMES=4", "--set", "LEVELS=1,2" })
        {
            start.ArgumentList.Add(a);
        }
        // The billiards of this build, beside the tests.
        start.Environment["BILLIARDS"] = "dotnet " + Path.Combine(AppContext.BaseDirectory, "billiards.dll");
        using var process = Process.Start(start)!;
        var stdout = process.StandardOutput.ReadToEndAsync();
        string stderr = await process.StandardError.ReadToEndAsync();
        await process.WaitForExitAsync();
        Assert.True(process.ExitCode == 0, stderr);
        for (int k = 0; k < 3; k++)
        {
            Assert.Contains($"selfplay {k}/3:", stderr, StringComparison.Ordinal);
        }

        var whole = CliRun.Run("selfplay", "--rules", "eight-ball", "--games", "4", "--levels", "1,2", "--seed", "9", "--out", Path.Combine(_dir, "all.jsonl"));
        Assert.True(whole.Code == 0, whole.Err);
        Assert.Equal(SelfplayShardTests.Counts(whole.Out), SelfplayShardTests.Counts(await stdout));
        Assert.Equal(SelfplayShardTests.Counts(whole.Out), SelfplayShardTests.Counts(File.ReadAllText(Path.Combine(data, "summary.json"))));
        Assert.Equal(File.ReadAllBytes(Path.Combine(_dir, "all.jsonl")), File.ReadAllBytes(Path.Combine(data, "games.jsonl")));
    }
}
