namespace Billiards.Core.Tests.Support;

/// <summary>Finds files of the repository from the test's output folder.</summary>
internal static class RepoPaths
{
    /// <summary>The folder holding Billiards.sln.</summary>
    public static string Root { get; } = FindRoot();

    /// <summary>A scene file under assets/scenes.</summary>
    public static string Scene(string name) => Path.Combine(Root, "assets", "scenes", name);

    private static string FindRoot()
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            if (File.Exists(Path.Combine(dir.FullName, "Billiards.sln")))
            {
                return dir.FullName;
            }
        }
        throw new InvalidOperationException("Billiards.sln not found above " + AppContext.BaseDirectory);
    }
}
