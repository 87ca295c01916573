namespace Billiards.App.Cli;

/// <summary>Finds the repository's assets: the folder holding Billiards.sln above the executable, else the current folder.</summary>
public static class AssetPaths
{
    /// <summary>The folder that holds <c>assets/</c>.</summary>
    public static string Root { get; } = Find();

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
