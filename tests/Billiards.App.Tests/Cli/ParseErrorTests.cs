using System.CommandLine;
using Billiards.App.Cli;

namespace Billiards.App.Tests.Cli;

/// <summary>
/// The parser's errors in a player's words, on one line with exit 2: every option of every verb
/// that takes a number, given a word instead, says "number" or "whole number", never the .NET type
/// the parser names ("System.Nullable`1[System.Int64]"); a verb of subcommands alone (report)
/// given none, or one it lacks, lists its subcommands.
/// </summary>
public sealed class ParseErrorTests
{
    private static readonly Type[] Whole = [typeof(int), typeof(long), typeof(short), typeof(uint), typeof(ulong), typeof(ushort), typeof(byte)];
    private static readonly Type[] Real = [typeof(double), typeof(float), typeof(decimal)];

    private static IEnumerable<(string[] Path, Option Option, bool IsWhole)> NumberOptions(Command command, string[] path)
    {
        foreach (var option in command.Options)
        {
            var type = Nullable.GetUnderlyingType(option.ValueType) ?? option.ValueType;
            if (Whole.Contains(type) || Real.Contains(type))
            {
                yield return (path, option, Whole.Contains(type));
            }
        }
        foreach (var sub in command.Subcommands)
        {
            foreach (var found in NumberOptions(sub, [.. path, sub.Name]))
            {
                yield return found;
            }
        }
    }

    [Fact]
    public void AWordForANumberIsRefusedInWordsForEveryNumberOption()
    {
        var root = CommandLine.Root(TextWriter.Null, TextWriter.Null);
        var options = NumberOptions(root, []).ToList();
        // selfplay's --seed (a long), simulate's --dt (a double), render's --width (an int) among them.
        Assert.Contains(options, o => o.Path.SequenceEqual(["selfplay"]) && o.Option.Name == "--seed");
        Assert.Contains(options, o => o.Path.SequenceEqual(["simulate"]) && o.Option.Name == "--dt" && !o.IsWhole);
        Assert.True(options.Count >= 20, $"{options.Count} number options");
        foreach (var (path, option, whole) in options)
        {
            var errors = root.Parse([.. path, option.Name, "x@"]).Errors.Select(e => CommandLine.Plain(e.Message)).ToList();
            string about = Assert.Single(errors, e => e.Contains($"'{option.Name}'", StringComparison.Ordinal));
            Assert.EndsWith(whole ? "expected type whole number." : "expected type number.", about, StringComparison.Ordinal);
            Assert.All(errors, e => Assert.DoesNotContain("System.", e, StringComparison.Ordinal));
        }
    }

    [Fact]
    public void TheProgramSaysItOnOneLineWithExit2()
    {
        var (code, stdout, stderr) = CliRun.Run("selfplay", "--rules", "eight-ball", "--levels", "1,1", "--seed", "abc");
        Assert.Equal(CommandLine.BadInput, code);
        Assert.Equal("", stdout);
        Assert.Equal("billiards: Cannot parse argument 'abc' for option '--seed' as expected type whole number.", stderr.TrimEnd('\n'));
    }

    [Theory]
    [InlineData(new string[] { "report" }, "billiards: report: expected one of accuracy, cushions, reality, snookers, ai (billiards report --help)")]
    [InlineData(new string[] { "report", "nope" }, "billiards: report nope: not one of accuracy, cushions, reality, snookers, ai (billiards report --help)")]
    public void AVerbOfSubcommandsGivenNoneOrAnUnknownOneListsThem(string[] args, string expected)
    {
        var (code, stdout, stderr) = CliRun.Run(args);
        Assert.Equal(CommandLine.BadInput, code);
        Assert.Equal("", stdout);
        Assert.Equal(expected, stderr.TrimEnd('\n'));
        var names = CommandLine.Root(TextWriter.Null, TextWriter.Null).Subcommands.Single(c => c.Name == "report").Subcommands.Select(c => c.Name);
        Assert.All(names, n => Assert.Contains(n, stderr, StringComparison.Ordinal));
    }
}
