using System.Diagnostics;
using System.Globalization;
using Billiards.Soak;

// billiards soak: seeded random legal shots through the engine's API, checked for NaN, escapes
// (a ball in play that is not at rest on the bed: its centre neither on the bed nor in a pocket's
// mouth, or inside a cushion), overlaps and runs that do not come to rest; balls off the table
// are counted apart. Usage:
//   dotnet run -c Release --project tests/Billiards.Soak -- --model standard --integrator exact --shots 1000000 --seed 1
//   dotnet run -c Release --project tests/Billiards.Soak -- --mix elevated --integrator event --shots 500000 --first 500000
var options = SoakOptions.Parse(args);
if (options is null)
{
    Console.Error.WriteLine("usage: Billiards.Soak [--model standard|thesis] [--integrator exact|event|euler|fixed] [--mix standard|elevated] [--shots N] [--first N] [--seed S] [--dt S] [--progress N] [--only K]");
    return 2;
}
var clock = Stopwatch.StartNew();
var report = new SoakReport();
var runner = new SoakRunner(options);
for (long shot = options.Only >= 0 ? options.Only : options.First; shot < (options.Only >= 0 ? options.Only + 1 : options.First + options.Shots); shot++)
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
