using System.Diagnostics;
using System.Globalization;
using Billiards.Soak;

// billiards soak: seeded random legal shots through the engine's API, checked for NaN, escapes
// (a ball that is not pocketed with its centre neither on the bed nor in a pocket's mouth), overlaps and runs that
// do not come to rest. Usage:
//   dotnet run -c Release --project tests/Billiards.Soak -- --model standard --integrator exact --shots 1000000 --seed 1
var options = SoakOptions.Parse(args);
if (options is null)
{
    Console.Error.WriteLine("usage: Billiards.Soak [--model standard|thesis] [--integrator exact|event|euler|fixed] [--shots N] [--seed S] [--dt S] [--progress N]");
    return 2;
}
var clock = Stopwatch.StartNew();
var report = new SoakReport();
var runner = new SoakRunner(options);
for (long shot = Math.Max(0, options.Only); shot < (options.Only >= 0 ? options.Only + 1 : options.Shots); shot++)
{
    report.Add(runner.RunShot(shot));
    if (options.Progress > 0 && (shot + 1) % options.Progress == 0)
    {
        Console.Error.WriteLine(string.Create(CultureInfo.InvariantCulture, $"[{clock.Elapsed.TotalSeconds:0}s] {report.Summary(options)}"));
    }
}
Console.WriteLine(report.Summary(options));
Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"wall {clock.Elapsed.TotalSeconds:0.0} s"));
return report.Failures == 0 ? 0 : 1;
