namespace Billiards.Core.Scenes;

/// <summary>
/// The program's own assets (fonts, table models, scenes, scripts): the folder <c>assets</c>
/// beside the executable (<see cref="AppContext.BaseDirectory"/>), where the build and
/// <c>dotnet publish</c> copy them. Never the working folder, so a program started from any
/// folder finds them; a path a user gives on the command line stays relative to the working folder.
/// </summary>
/// <remarks>
/// A program that takes Billiards.Core as a package ships no assets unless it copies its own
/// there; the engine itself reads none (scenes are loaded from a path or a JSON text).
/// </remarks>
public static class AssetFolder
{
    /// <summary>The <c>assets</c> folder beside the executable.</summary>
    public static string Assets { get; } = Path.Combine(AppContext.BaseDirectory, "assets");

    /// <summary>A file under <c>assets/scenes</c>, e.g. <c>Scene("eight-ball.json")</c> or <c>Scene("accuracy")</c>.</summary>
    public static string Scene(string relativePath) => Path.Combine(Assets, "scenes", relativePath);

    /// <summary>
    /// The full path of a shipped file, e.g. <c>File("fonts/DejaVuSansMono.ttf")</c>.
    /// </summary>
    /// <exception cref="AssetException">When the file is not there (<see cref="AssetException.Missing"/>).</exception>
    public static string File(string relativePath)
    {
        string path = Path.GetFullPath(Path.Combine(Assets, relativePath));
        return System.IO.File.Exists(path) ? path : throw AssetException.Missing(path);
    }

    /// <summary>Whether <paramref name="path"/> lies in the shipped assets (rather than being a user's file).</summary>
    public static bool Holds(string path) =>
        Path.GetFullPath(path).StartsWith(Path.GetFullPath(Assets) + Path.DirectorySeparatorChar, StringComparison.Ordinal);
}

/// <summary>
/// One of the program's own assets is missing or cannot be read: a problem of the installation,
/// not of the input. The message is one line that names the file and says which of the two it is.
/// </summary>
public sealed class AssetException : IOException
{
    private AssetException(string message) : base(message)
    {
    }

    /// <summary>The asset at <paramref name="path"/> is not there.</summary>
    public static AssetException Missing(string path) =>
        new($"{path}: missing asset (the program's assets belong in the folder assets beside its executable)");

    /// <summary>The asset at <paramref name="path"/> is there but cannot be read, for the reason <paramref name="why"/>.</summary>
    public static AssetException Unreadable(string path, string why) =>
        new($"{path}: unreadable asset ({why})");
}
