using System.CommandLine;
using Billiards.Core.Scenes;

namespace Billiards.App.Cli;

/// <summary>
/// The verbs of the executable (scene-format.md). A bad scene or argument gives one line on
/// stderr naming what is wrong and a non-zero exit; nothing is written half-way.
/// </summary>
/// <remarks>
/// The one error path of every verb, present and future: a verb's action throws, and
/// <see cref="Run"/> turns the exception into one line on stderr and an exit code, so no stack
/// trace ever reaches a user.
/// <list type="bullet">
/// <item><see cref="SceneException"/> and <see cref="CliException"/>: bad input, exit <see cref="BadInput"/> (2).</item>
/// <item><see cref="EnvironmentException"/>, I/O and access errors (a read-only disk, a full disk),
/// missing native libraries: an environment problem, exit <see cref="Failure"/> (1).</item>
/// <item>Anything else is a defect of the program: one line naming it, exit <see cref="Failure"/>.</item>
/// <item><c>simulate --batch</c> whose lines all ran but some gave an error record (written in their
/// place in the output): exit <see cref="BatchSimulation.SomeFailed"/> (3).</item>
/// </list>
/// A verb checks its arguments and every output path (<see cref="OutputFiles.Check"/>) before it
/// starts working, and writes its files with <see cref="OutputFiles.Write"/> (temporary file beside
/// the target, then a rename).
/// </remarks>
public static partial class CommandLine
{
    /// <summary>Exit code for bad input (scene or arguments).</summary>
    public const int BadInput = 2;

    /// <summary>Exit code for a failure that is not the input's fault (the environment, or a defect).</summary>
    public const int Failure = 1;

    /// <summary>Parses and runs a command line; returns the exit code.</summary>
    public static int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        try
        {
            var parse = Root(stdout, stderr).Parse(args);
            if (parse.Errors.Count > 0)
            {
                // A verb of subcommands alone ("report"): which ones there are, not "Required command was not provided".
                var command = parse.CommandResult.Command;
                string message = Plain(parse.Errors[0].Message);
                if (command is { Action: null, Subcommands.Count: > 0 })
                {
                    string names = string.Join(", ", command.Subcommands.Where(c => !c.Hidden).Select(c => c.Name));
                    message = parse.UnmatchedTokens.Count == 0
                        ? $"{command.Name}: expected one of {names} (billiards {command.Name} --help)"
                        : $"{command.Name} {parse.UnmatchedTokens[0]}: not one of {names} (billiards {command.Name} --help)";
                }
                return Fail(stderr, $"billiards: {message}", BadInput);
            }
            return parse.Invoke(new InvocationConfiguration { Output = stdout, Error = stderr, EnableDefaultExceptionHandler = false });
        }
        catch (Exception e)
        {
            var (message, code) = Classify(e);
            return Fail(stderr, message, code);
        }
    }

    /// <summary>The program's command: every verb with its options.</summary>
    internal static RootCommand Root(TextWriter stdout, TextWriter stderr)
    {
        var root = new RootCommand(VerbHelp.Root)
        {
            SimulateCommand.Create(stdout, stderr),
            RenderCommand.Create(stdout),
            RenderAudioCommand.Create(),
            ReportCommand.Create(stdout, stderr),
            SuggestCommand.Create(stdout),
            SelfplayCommand.Create(stdout, stderr),
            ReplayCommand.Create(stdout),
        };
        PlayCommand.AddTo(root);
        NetCommands.AddTo(root, stdout, stderr);
        VersionLine.Install(root);
        return root;
    }

    /// <summary>The line a user sees for an exception, and the exit code (see the remarks of <see cref="CommandLine"/>).</summary>
    public static (string Message, int Code) Classify(Exception e) => e switch
    {
        SceneException => (e.Message, BadInput),
        CliException => ($"billiards: {e.Message}", BadInput),
        EnvironmentException => ($"billiards: {e.Message}", Failure),
        IOException or UnauthorizedAccessException => ($"billiards: {e.Message}", Failure),
        DllNotFoundException or EntryPointNotFoundException or BadImageFormatException => ($"billiards: a native library is missing or unusable: {e.Message}", Failure),
        OutOfMemoryException or InsufficientExecutionStackException => ($"billiards: out of memory ({e.Message})", Failure),
        _ => ($"billiards: internal error ({e.GetType().Name}): {e.Message}", Failure),
    };

    private static int Fail(TextWriter stderr, string message, int code)
    {
        try
        {
            stderr.WriteLine(OneLine(message));
        }
        catch (IOException)
        {
            // stderr itself is gone: the exit code is all that is left.
        }
        return code;
    }

    /// <summary>A message on one line: line breaks become spaces.</summary>
    public static string OneLine(string message) =>
        message.Replace("\r\n", " ", StringComparison.Ordinal).Replace('\n', ' ').Replace('\r', ' ');

    // System.CommandLine names CLR types in its messages ("System.Nullable`1[System.Double]").
    /// <summary>
    /// A parse error in a player's words: the .NET type an option expects ("'System.Nullable`1[System.Int64]'")
    /// named as "number" or "whole number".
    /// </summary>
    internal static string Plain(string message) => TypeName().Replace(message, m => m.Groups[1].Value switch
    {
        "Double" or "Single" or "Decimal" => "number",
        "Int16" or "Int32" or "Int64" or "UInt16" or "UInt32" or "UInt64" or "Byte" or "SByte" => "whole number",
        "Boolean" => "true or false",
        string other => other.ToLowerInvariant(),
    });

    [System.Text.RegularExpressions.GeneratedRegex(@"'System\.(?:Nullable`1\[System\.)?(\w+)\]?'")]
    private static partial System.Text.RegularExpressions.Regex TypeName();
}

/// <summary>A bad command-line argument, reported as one line with exit code 2.</summary>
public sealed class CliException(string message) : Exception(message);

/// <summary>
/// A problem of the environment rather than of the input (no display, no audio device, a folder
/// that cannot be written), reported as one line with exit code 1.
/// </summary>
public sealed class EnvironmentException(string message, Exception? inner = null) : Exception(message, inner);
