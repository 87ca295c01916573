using Billiards.Core.Rules;

namespace Billiards.Core.Tests.Rules;

/// <summary>The game's own part of a ruling read as the tests assert it: a ruling of another game has none and fails the test.</summary>
internal static class RulingParts
{
    extension(Ruling ruling)
    {
        public bool Point => ThreeCushion(ruling).Point;

        public int Cushions => ThreeCushion(ruling).Cushions;

        public int Run => ThreeCushion(ruling).Run;

        public PerPlayer<int> Innings => ThreeCushion(ruling).Innings;

        public bool FoulAndMiss => Snooker(ruling).FoulAndMiss;

        public bool FreeBall => Snooker(ruling).FreeBall;
    }

    private static ThreeCushionRulingPart ThreeCushion(Ruling ruling) =>
        ruling.PartOf<ThreeCushionRulingPart>() ?? throw new Xunit.Sdk.XunitException($"not a three-cushion ruling: {ruling.Message}");

    private static SnookerRulingPart Snooker(Ruling ruling) =>
        ruling.PartOf<SnookerRulingPart>() ?? throw new Xunit.Sdk.XunitException($"not a snooker ruling: {ruling.Message}");
}
