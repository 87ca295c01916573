using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Rules;

/// <summary>Core's match drives snooker frames with real physics: the break-off, the options after a foul, replace, and records that replay.</summary>
public class SnookerMatchTests
{
    private static readonly BallId Cue = BallSet.Snooker.CueBalls[0];

    private static readonly Vec3 BreakPlace = new(SnookerTable.BaulkLineX(TableSpec.FromPreset("snooker-12ft")), -0.146, 0.02625);

    // The break-off into the side of the pack, then the incoming player plays away from every ball (a foul and a miss).
    private static Match Opening(RefereeOption choice)
    {
        var match = new Match(GameSetup.Of(GameRules.Snooker, 1, new("Anna", "Ben")));
        // Cue speeds of an elastic tip's 7.0 and 0.6 m/s with the leather tip's (1 + 0.73) / 2.
        var breakOff = match.Play(new GameShot(new ShotSpec(7.0 * 2 / 1.73, 2.6), Place: BreakPlace));
        Assert.True(breakOff.Ruling.Legal, breakOff.Ruling.Message);
        Assert.Equal(1, match.State.Shooter);
        // Straight at the baulk cushion and back, short of every ball.
        match.Play(new GameShot(new ShotSpec(0.6 * 2 / 1.73, 180), Choice: choice));
        return match;
    }

    /// <summary>
    /// Seeded random shots through a frame (random strikes, nominations, placements in the D and
    /// choices among the options offered): every ruling applies, the score only grows, no two balls
    /// overlap between shots, and the record of it all replays.
    /// </summary>
    [Theory]
    [InlineData(26)]
    [InlineData(7)]
    [InlineData(1234)]
    [InlineData(99)]
    public void RandomShotsThroughAFrameApplyEveryRulingAndReplay(int seed)
    {
        var random = new Random(seed);
        var match = new Match(GameSetup.Of(GameRules.Snooker, 3));
        double r = match.Setup.BallRadius;
        for (int i = 0; i < 80 && !match.IsOver; i++)
        {
            var state = match.State;
            var colours = match.Balls.Ids.Where(SnookerRuleset.IsColour).ToList();
            Call? call = SnookerPart.Of(state).BallOn == "colour" && colours.Count > 0 ? Call.Nominate(colours[random.Next(colours.Count)]) : null;
            Vec3? place = match.BallInHand == BallInHand.D
                ? new Vec3(SnookerTable.BaulkLineX(match.Setup.Table) - (random.NextDouble() * 0.2), (random.NextDouble() - 0.5) * 0.4, r)
                : null;
            var input = new GameShot(new ShotSpec(1 + (random.NextDouble() * 6), random.NextDouble() * 360, (random.NextDouble() - 0.5) * 0.6, (random.NextDouble() - 0.5) * 0.6), call, place);
            var sim = match.Strike(input);
            Match.RunToRest(sim);
            var shot = match.Judge(sim);
            if (match.PendingOptions.Count > 0)
            {
                match.Choose(match.PendingOptions[random.Next(match.PendingOptions.Count)]);
            }
            // (A frame's end starts the next frame's state at 0 - 0.)
            Assert.True(match.IsOver || match.State.Score.First >= shot.Before.Score.First && match.State.Score.Second >= shot.Before.Score.Second,
                $"shot {i}: {shot.Before.Score} -> {match.State.Score}: {match.Shots[^1].Ruling.Message} ({match.Shots[^1].Input.Choice})");
            var balls = match.Balls.Positions.ToList();
            for (int a = 0; a < balls.Count; a++)
            {
                for (int b = a + 1; b < balls.Count; b++)
                {
                    Assert.True((balls[a] - balls[b]).LengthXY >= 2 * r - 1e-6, $"shot {i}: two balls overlap");
                }
            }
        }
        var record = GameRecordFile.Parse(System.Text.Encoding.UTF8.GetString(GameRecordFile.ToUtf8(match)), "random.json");
        Assert.Equal(-1, GameRecordFile.Replay(record, out _));
    }

    [Fact]
    public void ASnookerFrameStartsFromItsRackOnItsTableWithTheCueBallInHandInTheD()
    {
        var match = new Match(GameSetup.Of(GameRules.Snooker, 1));
        Assert.Equal("snooker-12ft", match.Setup.Table.Preset);
        Assert.Equal(0.02625, match.Setup.BallRadius);
        Assert.Equal(22, match.Balls.Count);
        Assert.Equal(BallInHand.D, match.BallInHand);
        Assert.True(SnookerTable.InD(match.Setup.Table, match.Balls[Cue]));
    }

    [Fact]
    public void ReplaceAfterAFoulAndAMissPutsEveryBallBackAndTheOffenderPlaysAgain()
    {
        var match = Opening(RefereeOption.Replace);
        var miss = match.Shots[^1];
        Assert.True(miss.Ruling.FoulAndMiss, miss.Ruling.Message);
        Assert.Equal([Foul.NoContact], miss.Ruling.Fouls);
        var before = match.Shots[0].After.ToDictionary(b => b.Id, b => b.Position);
        Assert.Equal(before.Count, match.Balls.Count);
        Assert.All(before, b => Assert.Equal(b.Value, match.Balls[b.Key]));
        Assert.Equal(1, match.State.Shooter);
        Assert.Equal(new PerPlayer<int>(4, 0), match.State.Score);
        Assert.Equal(new PerPlayer<int>(0, 1), SnookerPart.Of(match.State).MissesInRow);
    }

    [Fact]
    public void PlayAfterAFoulLeavesTheBallsWhereTheyLieForTheIncomingPlayer()
    {
        var match = Opening(RefereeOption.Play);
        var lie = match.Shots[^1].After.ToDictionary(b => b.Id, b => b.Position);
        Assert.All(lie, b => Assert.Equal(b.Value, match.Balls[b.Key]));
        Assert.NotEqual(match.Shots[0].After.Single(b => b.Id == Cue).Position, match.Balls[Cue]);
        Assert.Equal(0, match.State.Shooter);
    }

    // The opening, a replaced miss, a put-back, and on.
    private static Match Scripted()
    {
        var match = Opening(RefereeOption.Replace);
        match.Play(new GameShot(new ShotSpec(2.0, 10), Choice: RefereeOption.PutBack));
        match.Play(new GameShot(new ShotSpec(3.0, -15), Call: Call.Nominate(BallSet.Colour("blue"))));
        return match;
    }

    /// <summary>
    /// The committed record (assets/records/snooker-opening.json, what <c>replay --verify</c>
    /// reads) replays shot for shot. To write it again: BILLIARDS_WRITE_RECORDS=1 dotnet test --filter The_committed_snooker_record.
    /// </summary>
    [Fact]
    public void TheCommittedSnookerRecordReplaysWithVerify()
    {
        string path = AssetFolder.File("records/snooker-opening.json");
        if (Environment.GetEnvironmentVariable("BILLIARDS_WRITE_RECORDS") == "1")
        {
            byte[] bytes = GameRecordFile.ToUtf8(Scripted());
            File.WriteAllBytes(Path.Combine(SourceFolder(), "..", "..", "..", "assets", "records", "snooker-opening.json"), bytes);
            File.WriteAllBytes(path, bytes);
        }
        var record = GameRecordFile.Parse(File.ReadAllText(path), path);
        var report = GameRecordFile.Verify(record, out _);
        Assert.Null(report.FirstDifference);
        Assert.Equal(record.Shots.Count, report.Same);
        Assert.True(report.Shots >= 4);
    }

    private static string SourceFolder([System.Runtime.CompilerServices.CallerFilePath] string file = "") => Path.GetDirectoryName(file)!;

    [Fact]
    public void ARecordedSnookerFrameReplaysRulingForRuling()
    {
        var match = Scripted();
        var text = System.Text.Encoding.UTF8.GetString(GameRecordFile.ToUtf8(match));
        Assert.Contains("\"ball_on\"", text, StringComparison.Ordinal);
        Assert.Contains("\"foul_and_miss\": true", text, StringComparison.Ordinal);
        var record = GameRecordFile.Parse(text, "frame.json");
        Assert.Equal(match.Shots.Count, record.Shots.Count);
        Assert.Equal(-1, GameRecordFile.Replay(record, out var replayed));
        Assert.Equal(match.State, replayed.State);
    }
}
