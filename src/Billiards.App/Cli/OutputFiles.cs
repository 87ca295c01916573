namespace Billiards.App.Cli;

/// <summary>
/// Output files of every verb: checked before any work starts, written atomically (a temporary
/// file beside the target, renamed into place), and the temporary files removed on any failure.
/// </summary>
public static class OutputFiles
{
    /// <summary>
    /// Checks that <paramref name="path"/> can name a file to write: not empty, not a folder, in a
    /// folder that exists and can be written, with the expected extension if one is given.
    /// </summary>
    /// <param name="option">The option that named the path, for the message (e.g. "--out").</param>
    /// <param name="path">The path as the user typed it.</param>
    /// <param name="extension">The required extension with its dot (".png"), or null.</param>
    /// <returns>The full path.</returns>
    /// <exception cref="CliException">When the path cannot name a file (bad input).</exception>
    /// <exception cref="EnvironmentException">When its folder cannot be written.</exception>
    public static string Check(string option, string path, string? extension = null)
    {
        string full = FullPath(option, path);
        if (EndsInSeparator(path) || Directory.Exists(full))
        {
            throw new CliException($"{option} {Show(path)}: names a folder; expected a file");
        }
        if (extension is not null && !full.EndsWith(extension, StringComparison.OrdinalIgnoreCase))
        {
            throw new CliException($"{option} {Show(path)}: expected a {extension} file");
        }
        string folder = Path.GetDirectoryName(full) ?? full;
        if (!Directory.Exists(folder))
        {
            throw new CliException($"{option} {Show(path)}: the folder {folder} does not exist");
        }
        Probe(option, path, folder);
        return full;
    }

    /// <summary>
    /// Checks that <paramref name="path"/> can name a folder to write files into: not empty, not a
    /// file, and either an existing writable folder or one that can be created under an existing
    /// folder; and that none of <paramref name="names"/> inside it is a folder. Creates nothing.
    /// </summary>
    /// <returns>The full path of the folder.</returns>
    public static string CheckFolder(string option, string path, params string[] names)
    {
        string full = FullPath(option, path);
        if (File.Exists(full))
        {
            throw new CliException($"{option} {Show(path)}: is a file; expected a folder");
        }
        string existing = full;
        while (!Directory.Exists(existing))
        {
            if (File.Exists(existing))
            {
                throw new CliException($"{option} {Show(path)}: {existing} is a file, so the folder cannot be made");
            }
            existing = Path.GetDirectoryName(existing) ?? throw new CliException($"{option} {Show(path)}: no existing folder above it");
        }
        foreach (string name in names)
        {
            if (Directory.Exists(Path.Combine(full, name)))
            {
                throw new CliException($"{option} {Show(path)}: {name} in it is a folder; expected a file or nothing");
            }
        }
        Probe(option, path, existing);
        return full;
    }

    /// <summary>Writes one file atomically (see <see cref="WriteAll"/>).</summary>
    public static void Write(string path, ReadOnlySpan<byte> bytes) => WriteAll([(path, bytes.ToArray())]);

    /// <summary>
    /// Writes one file atomically as <see cref="WriteAll"/> does, but from a writer that streams
    /// into it (for outputs too large to hold in memory, such as <c>simulate --batch</c>): the
    /// temporary file is renamed into place only when <paramref name="write"/> returns.
    /// </summary>
    public static void WriteStreaming(string path, Action<Stream> write)
    {
        ArgumentNullException.ThrowIfNull(write);
        string target = Path.GetFullPath(path);
        string temp = TempName(target);
        try
        {
            using (var stream = new FileStream(temp, FileMode.CreateNew, FileAccess.Write, FileShare.None, 1 << 16))
            {
                write(stream);
                stream.Flush(flushToDisk: true);
            }
            File.Move(temp, target, overwrite: true);
        }
        finally
        {
            TryDelete(temp);
        }
    }

    /// <summary>
    /// Writes files so that each appears whole or not at all: every file goes to a temporary file
    /// beside its target first, and only when all are written are they renamed into place. On any
    /// failure every temporary file is deleted and the error passes on.
    /// </summary>
    public static void WriteAll(IReadOnlyList<(string Path, byte[] Bytes)> files)
    {
        var temps = new List<(string Temp, string Target)>();
        try
        {
            foreach (var (path, bytes) in files)
            {
                string target = Path.GetFullPath(path);
                string temp = TempName(target);
                temps.Add((temp, target));
                using (var stream = new FileStream(temp, FileMode.CreateNew, FileAccess.Write))
                {
                    stream.Write(bytes);
                    stream.Flush(flushToDisk: true);
                }
            }
            for (int i = 0; i < temps.Count; i++)
            {
                File.Move(temps[i].Temp, temps[i].Target, overwrite: true);
            }
        }
        finally
        {
            foreach (var (temp, _) in temps)
            {
                TryDelete(temp);
            }
        }
    }

    private static string FullPath(string option, string path)
    {
        if (string.IsNullOrWhiteSpace(path))
        {
            throw new CliException($"{option}: the path is empty");
        }
        if (path.Contains('\0', StringComparison.Ordinal))
        {
            throw new CliException($"{option} {Show(path)}: the path contains a NUL character");
        }
        try
        {
            return Path.GetFullPath(path);
        }
        catch (Exception e) when (e is ArgumentException or NotSupportedException or PathTooLongException)
        {
            throw new CliException($"{option} {Show(path)}: not a usable path ({e.Message})");
        }
    }

    // Creating (and removing) a file in the folder is the only sure test that it can be written.
    private static void Probe(string option, string path, string folder)
    {
        string probe = TempName(Path.Combine(folder, ".billiards-probe"));
        try
        {
            using (new FileStream(probe, FileMode.CreateNew, FileAccess.Write, FileShare.None, 1, FileOptions.DeleteOnClose))
            {
            }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new EnvironmentException($"{option} {Show(path)}: cannot write in {folder} ({e.Message})", e);
        }
        finally
        {
            TryDelete(probe);
        }
    }

    private static int s_counter;

    private static string TempName(string target) =>
        $"{target}.tmp-{Environment.ProcessId}-{Interlocked.Increment(ref s_counter)}";

    private static void TryDelete(string path)
    {
        try
        {
            File.Delete(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            // Nothing more can be done; the original error is what the user needs to see.
        }
    }

    private static bool EndsInSeparator(string path) =>
        path.EndsWith(Path.DirectorySeparatorChar) || path.EndsWith(Path.AltDirectorySeparatorChar)
        || Path.GetFileName(path) is "." or "..";

    private static string Show(string path) => path.Length > 200 ? path[..200] + "..." : path;
}
