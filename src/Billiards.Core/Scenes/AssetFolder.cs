namespace Billiards.Core.Scenes;

/// <summary>
/// Where the shipped assets live (<c>assets/scenes</c>, <c>assets/models</c>): the nearest folder
/// above the executable that holds <c>assets/scenes</c>, else the nearest above the working folder,
/// else the working folder itself. So the game, the tests and the benchmarks find the scenes
/// whether they run from the repository or from a build folder below it.
/// </summary>
public static class AssetFolder
{
    /// <summary>The folder that holds <c>assets/</c>.</summary>
    public static string Root { get; } = Find();

    /// <summary>The <c>assets</c> folder.</summary>
    public static string Assets => Path.Combine(Root, "assets");

    /// <summary>A file under <c>assets/scenes</c>, e.g. <c>Scene("eight-ball.json")</c> or <c>Scene("accuracy")</c>.</summary>
    public static string Scene(string relativePath) => Path.Combine(Root, "assets", "scenes", relativePath);

    private static string Find()
    {
        foreach (string start in new[] { AppContext.BaseDirectory, Directory.GetCurrentDirectory() })
        {
            for (var dir = new DirectoryInfo(start); dir is not null; dir = dir.Parent)
            {
                if (Directory.Exists(Path.Combine(dir.FullName, "assets", "scenes")))
                {
                    return dir.FullName;
                }
            }
        }
        return Directory.GetCurrentDirectory();
    }
}
