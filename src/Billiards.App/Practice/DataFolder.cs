namespace Billiards.App.Practice;

/// <summary>
/// The user's data folder, where practice keeps its drill results and saved positions:
/// <c>$BILLIARDS_DATA_DIR</c> when set (tests, portable installs; <c>play --data DIR</c> too), else
/// <c>$XDG_DATA_HOME/billiards</c>, else <c>~/.local/share/billiards</c> on Linux and the BSDs,
/// <c>%APPDATA%\billiards</c> on Windows, <c>~/Library/Application Support/billiards</c> on macOS.
/// </summary>
public static class DataFolder
{
    /// <summary>The environment variable that redirects the data folder.</summary>
    public const string Variable = "BILLIARDS_DATA_DIR";

    /// <summary>The data folder of this user (not created).</summary>
    public static string Path(Func<string, string?>? environment = null)
    {
        environment ??= Environment.GetEnvironmentVariable;
        if (environment(Variable) is { Length: > 0 } chosen)
        {
            return System.IO.Path.GetFullPath(chosen);
        }
        if (OperatingSystem.IsWindows())
        {
            string appData = environment("APPDATA") is { Length: > 0 } a ? a : Environment.GetFolderPath(Environment.SpecialFolder.ApplicationData);
            return System.IO.Path.Combine(appData, "billiards");
        }
        string home = environment("HOME") is { Length: > 0 } h ? h : Environment.GetFolderPath(Environment.SpecialFolder.UserProfile);
        if (OperatingSystem.IsMacOS())
        {
            return System.IO.Path.Combine(home, "Library", "Application Support", "billiards");
        }
        string data = environment("XDG_DATA_HOME") is { Length: > 0 } x ? x : System.IO.Path.Combine(home, ".local", "share");
        return System.IO.Path.Combine(data, "billiards");
    }
}
