using Billiards.App.Cli;

namespace Billiards.App.Tests.Cli;

/// <summary>Runs the command line in-process, as the executable does, capturing both streams.</summary>
internal static class CliRun
{
    public static (int Code, string Out, string Err) Run(params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int code = CommandLine.Run(args, stdout, stderr);
        return (code, stdout.ToString(), stderr.ToString());
    }
}
