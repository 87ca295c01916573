using System.CommandLine;
using Billiards.Core.Scenes;

namespace Billiards.App.Cli;

/// <summary>
/// The verbs of the executable (scene-format.md). A bad scene or argument gives one line on
/// stderr naming what is wrong and a non-zero exit; nothing is written half-way.
/// </summary>
public static class CommandLine
{
    /// <summary>Exit code for bad input (scene or arguments).</summary>
    public const int BadInput = 2;

    /// <summary>Exit code for a failure that is not the input's fault.</summary>
    public const int Failure = 1;

    /// <summary>Parses and runs a command line; returns the exit code.</summary>
    public static int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        var root = new RootCommand("Billiards: a pool game and billiards physics engine.")
        {
            SimulateCommand.Create(stdout),
            RenderCommand.Create(stdout),
            RenderAudioCommand.Create(),
            ReportCommand.Create(stdout, stderr),
        };
        PlayCommand.AddTo(root);
        var parse = root.Parse(args);
        if (parse.Errors.Count > 0)
        {
            stderr.WriteLine($"billiards: {Plain(parse.Errors[0].Message)}");
            return BadInput;
        }
        try
        {
            return parse.Invoke(new InvocationConfiguration { Output = stdout, Error = stderr, EnableDefaultExceptionHandler = false });
        }
        catch (SceneException e)
        {
            stderr.WriteLine(e.Message);
            return BadInput;
        }
        catch (CliException e)
        {
            stderr.WriteLine($"billiards: {e.Message}");
            return BadInput;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            stderr.WriteLine($"billiards: {e.Message}");
            return Failure;
        }
    }

    // System.CommandLine names CLR types in its messages ("System.Nullable`1[System.Double]").
    private static string Plain(string message) =>
        message.Replace("'System.Nullable`1[System.Double]'", "number").Replace("'System.Double'", "number")
               .Replace("'System.Int32'", "whole number");

    /// <summary>Writes bytes to a file only once they are complete: a temporary file renamed into place.</summary>
    public static void WriteAtomically(string path, ReadOnlySpan<byte> bytes)
    {
        string full = Path.GetFullPath(path);
        string? dir = Path.GetDirectoryName(full);
        if (dir is not null && !Directory.Exists(dir))
        {
            throw new CliException($"--out {path}: the folder {dir} does not exist");
        }
        string temp = full + ".tmp-" + Environment.ProcessId;
        File.WriteAllBytes(temp, bytes.ToArray());
        File.Move(temp, full, overwrite: true);
    }
}

/// <summary>A bad command-line argument, reported as one line.</summary>
public sealed class CliException(string message) : Exception(message);
