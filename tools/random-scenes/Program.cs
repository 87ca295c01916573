using System.Globalization;
using Billiards.Tools;

// Usage: dotnet run --project tools/random-scenes -c Release -- COUNT SEED [standard|elevated] > scenes.jsonl
// Scene k of seed S and a mix is the same on every run and machine (RandomScenes).
if (args.Length is not (2 or 3)
    || !int.TryParse(args[0], NumberStyles.None, CultureInfo.InvariantCulture, out int count) || count < 1
    || !ulong.TryParse(args[1], NumberStyles.None, CultureInfo.InvariantCulture, out ulong seed)
    || (args.Length == 3 && args[2] is not (RandomScenes.StandardMix or RandomScenes.ElevatedMix)))
{
    Console.Error.WriteLine("usage: random-scenes COUNT SEED [standard|elevated] (COUNT >= 1; writes COUNT scenes, one per line, to stdout; the elevated mix: issue 40's strokes)");
    return 2;
}
string mix = args.Length == 3 ? args[2] : RandomScenes.StandardMix;
using var stdout = Console.OpenStandardOutput();
for (int k = 0; k < count; k++)
{
    stdout.Write(RandomScenes.Line(seed, k, mix));
}
return 0;
