// Paired run-out trials of level 5 playing for the noise, 8-ball at 1x: each rack (seeded) is broken
// once by the planner as it is, then every variant of the planner tries to run it out from that
// break with the same draws of the noise; a line a rack, then each variant's run-outs and how many
// racks it ran out that the first variant did not, and the reverse. With --keep, the chosen break
// of each rack struck again with fresh draws: how often it keeps the table against what the
// search expected.
//
//   dotnet run --project tools/ai/run-out -c Release -- RACKS FIRST VARIANT [VARIANT ...]
//   dotnet run --project tools/ai/run-out -c Release -- --keep RACKS FIRST DRAWS
//
// A variant is the planner as it is (base) with changes joined by '+': stay=S (staying S, the
// position 1-S), second=W (the best shot on another ball), posaim=DEG (the aim error a position is
// judged with, before the 2.5x), candidates=N, first-round=N (simulations), screen=TOP:SAMPLES,
// refine=TOP:SAMPLES.
using System.Globalization;
using Billiards.Core.Ai;
using Billiards.Core.Rules;
using Billiards.Core.Table;

var noise = new ExecutionNoise(ExecutionNoise.FastFiz, 1);
var planned = SkillLevel.Of(5).PlayingFor(noise);
var rules = GameRules.EightBall;
var table = TableSpec.FromPreset(Ruleset.For(rules).TablePreset);
var physics = Ruleset.For(rules).BallSet.DefaultParams;
var budget = new PlannerBudget(600_000, 1);
const ulong Seed = 4242;
const long NoiseStream = 3;

if (args.Length >= 1 && args[0] == "--keep")
{
    Keep(int.Parse(args[1], CultureInfo.InvariantCulture), int.Parse(args[2], CultureInfo.InvariantCulture), int.Parse(args[3], CultureInfo.InvariantCulture));
    return 0;
}
if (args.Length < 3)
{
    Console.Error.WriteLine("usage: run-out RACKS FIRST VARIANT [VARIANT ...] | --keep RACKS FIRST DRAWS");
    return 2;
}
int racks = int.Parse(args[0], CultureInfo.InvariantCulture), first = int.Parse(args[1], CultureInfo.InvariantCulture);
string[] names = args[2..];
var variants = names.Select(Variant).ToArray();
var ran = new bool[racks, variants.Length];
var gate = new object();
Parallel.For(first, first + racks, new ParallelOptions { MaxDegreeOfParallelism = Environment.ProcessorCount }, i =>
{
    var planner = new ShotPlanner(table, physics);
    ulong seed = PlannerRandom.Derive(Seed, i);
    Decision? opening = null;
    var line = new List<string>();
    for (int v = 0; v < variants.Length; v++)
    {
        var session = NewSession(planner, seed);
        var game = session.Game;
        int k = 0;
        bool kept = true;
        for (; k < 60 && !game.IsOver && kept; k++)
        {
            var state = game.State;
            if (state.Shooter != 0)
            {
                break;
            }
            var position = new TablePosition(game.Balls.OrderBy(b => b.Id.Value), game.Ruleset.CueBall(state));
            var d = k == 0
                ? opening ??= planner.Decide(state, position, planned, budget, PlannerRandom.Derive(seed, k, 1))
                : planner.Decide(state, position, variants[v], budget, PlannerRandom.Derive(seed, k, 1));
            var place = game.BallInHand == BallInHand.None ? null : d.Place;
            var struck = noise.Apply(d.Shot, new PlannerRandom(PlannerRandom.Derive(seed, k, NoiseStream)), planner.Table.R);
            var played = session.Play(new GameShot(struck, d.Call, place, d.PushOut), SeatKind.Computer,
                judged => planner.ChooseOption(judged.Ruling, new TablePosition(judged.After, game.Ruleset.CueBall(judged.Ruling.Next))));
            kept = k > 0 || played.Ruling.Continue;
        }
        bool won = game.IsOver && game.Shots.All(s => s.Before.Shooter == 0) && game.Shots[^1].Ruling.Winner == 0;
        ran[i - first, v] = won;
        line.Add(string.Create(CultureInfo.InvariantCulture, $"{(won ? 1 : 0)}/{game.Shots.Count}"));
    }
    lock (gate)
    {
        Console.WriteLine($"{i} {string.Join(' ', line)}");
    }
});
for (int v = 0; v < variants.Length; v++)
{
    int total = 0, better = 0, worse = 0;
    for (int r = 0; r < racks; r++)
    {
        total += ran[r, v] ? 1 : 0;
        better += ran[r, v] && !ran[r, 0] ? 1 : 0;
        worse += !ran[r, v] && ran[r, 0] ? 1 : 0;
    }
    Console.WriteLine($"{names[v]}: ran out {total} of {racks} racks; {better} that {names[0]} did not, {worse} that it did");
}
return 0;

Session NewSession(ShotPlanner planner, ulong seed)
{
    int rackSeed = (int)(PlannerRandom.Derive(seed, 7_000_000) & 0x3FFFFFFF);
    var setup = new GameSetup(table, planner.PhysicsConfig, rackSeed, Ruleset.For(rules).BrokenBy(new GameState(rules), 0));
    return new Session(setup, Seat.Of(setup.Start.Players, SeatKind.Computer));
}

SkillLevel Variant(string name)
{
    var level = planned;
    foreach (string part in name.Split('+'))
    {
        string[] kv = part.Split('=');
        string value = kv.Length > 1 ? kv[1] : "0";
        double x = double.TryParse(value, CultureInfo.InvariantCulture, out double d) ? d : 0;
        int[] pair = value.Contains(':', StringComparison.Ordinal) ? [.. value.Split(':').Select(p => int.Parse(p, CultureInfo.InvariantCulture))] : [0, 0];
        level = kv[0] switch
        {
            "base" => level,
            "stay" => level with { Leave = level.Leave with { Stay = x, Position = 1 - x } },
            "second" => level with { Leave = level.Leave with { SecondShot = x } },
            "posaim" => level with { AimStdDeg = x },
            "candidates" => level with { Candidates = (int)x },
            "first-round" => level with { FirstRoundSimulations = (int)x },
            "screen" => level with { ScreenTop = pair[0], ScreenSamples = pair[1] },
            "refine" => level with { RefineTop = pair[0], RefineSamples = pair[1] },
            _ => throw new ArgumentException($"{part}: not a variant"),
        };
    }
    return level;
}

void Keep(int count, int from, int draws)
{
    double expected = 0, measured = 0;
    var lockObject = new object();
    Parallel.For(from, from + count, new ParallelOptions { MaxDegreeOfParallelism = Environment.ProcessorCount }, i =>
    {
        var planner = new ShotPlanner(table, physics);
        ulong seed = PlannerRandom.Derive(Seed, i);
        var start = NewSession(planner, seed);
        var state = start.Game.State;
        var d = planner.Decide(state, new TablePosition(start.Game.Balls.OrderBy(b => b.Id.Value), start.Game.Ruleset.CueBall(state)), planned, budget, PlannerRandom.Derive(seed, 0, 1));
        int kept = 0;
        for (int t = 0; t < draws; t++)
        {
            var struck = noise.Apply(d.Shot, new PlannerRandom(PlannerRandom.Derive(seed, 99, 1000 + t)), planner.Table.R);
            kept += NewSession(planner, seed).Play(new GameShot(struck, d.Call, d.Place, d.PushOut), SeatKind.Computer, _ => null).Ruling.Continue ? 1 : 0;
        }
        lock (lockObject)
        {
            expected += d.ExpectedPot;
            measured += (double)kept / draws;
            Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{i} expected {d.ExpectedPot:F2} kept {kept} of {draws}"));
        }
    });
    Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{count} racks: the search expected {expected / count:P1}, the break kept the table {measured / count:P1}"));
}
