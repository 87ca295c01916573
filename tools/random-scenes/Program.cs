using System.Globalization;
using Billiards.Tools;

// Usage: dotnet run --project tools/random-scenes -c Release -- COUNT SEED > scenes.jsonl
// Scene k of seed S is the same on every run and machine (RandomScenes).
if (args.Length != 2
    || !int.TryParse(args[0], NumberStyles.None, CultureInfo.InvariantCulture, out int count) || count < 1
    || !ulong.TryParse(args[1], NumberStyles.None, CultureInfo.InvariantCulture, out ulong seed))
{
    Console.Error.WriteLine("usage: random-scenes COUNT SEED (COUNT >= 1; writes COUNT scenes, one per line, to stdout)");
    return 2;
}
using var stdout = Console.OpenStandardOutput();
for (int k = 0; k < count; k++)
{
    stdout.Write(RandomScenes.Line(seed, k));
}
return 0;
