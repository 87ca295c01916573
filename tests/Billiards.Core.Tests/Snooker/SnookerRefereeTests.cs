using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Rules;
using Billiards.Core.Table;
using static Billiards.Core.Tests.Snooker.SnookerShot;

namespace Billiards.Core.Tests.Snooker;

/// <summary>One test for each rule of rules.md's "Snooker", named after the rule.</summary>
public class SnookerRefereeTests
{
    private static readonly GameState OnRed = Frame;

    // One red left on the rack's apex, the blue and black on their spots, the cue ball with a full view of the red.
    private static SnookerShot Clear() => new SnookerShot().Only("red-1", "blue", "black").At("cue", -1.0, 0.3);

    private static GameState OnColour(string nominated) => Frame with { BallOn = "colour", Call = Call.Nominate(Id(nominated)) };

    [Fact]
    public void Values_red_1_yellow_2_green_3_brown_4_blue_5_pink_6_black_7()
    {
        Assert.Equal([1, 2, 3, 4, 5, 6, 7], new[] { "red-9", "yellow", "green", "brown", "blue", "pink", "black" }.Select(n => SnookerRuleset.ValueOf(Id(n))));
        // The value is what a potted ball on scores.
        foreach (string colour in BallSet.Colours)
        {
            var ruling = new SnookerShot().Hit(colour).Pot(colour).Judge(OnColour(colour));
            Assert.Equal(SnookerRuleset.ValueOf(Id(colour)), ruling.Points);
            Assert.Equal(ruling.Points, ruling.Next.Score.First);
        }
    }

    [Fact]
    public void Ball_on_red_while_reds_remain_each_red_potted_scores_1_and_a_colour_is_on_next()
    {
        var ruling = new SnookerShot().Hit("red-3").Pot("red-3").Pot("red-7").Judge(OnRed);
        Assert.True(ruling.Legal && ruling.Continue);
        Assert.Equal(2, ruling.Points);
        Assert.Equal(new PerPlayer<int>(2, 0), ruling.Next.Score);
        Assert.Equal("colour", ruling.Next.BallOn);
        Assert.Empty(ruling.Spot);
    }

    [Fact]
    public void Ball_on_colour_the_nominated_colour_potted_while_reds_remain_scores_and_is_respotted_and_a_red_is_on_next()
    {
        var ruling = new SnookerShot().Gone("red-1").Hit("blue").Pot("blue").Judge(OnColour("blue"));
        Assert.True(ruling.Legal && ruling.Continue);
        Assert.Equal(5, ruling.Points);
        Assert.Equal([Id("blue")], ruling.Spot);
        Assert.Equal("red", ruling.Next.BallOn);
    }

    [Fact]
    public void Ball_on_colour_a_colour_other_than_the_nominated_one_struck_first_is_a_foul()
    {
        var ruling = new SnookerShot().Hit("pink").Judge(OnColour("blue"));
        Assert.Equal([Foul.WrongBallFirst], ruling.Fouls);
        Assert.Equal(6, ruling.Penalty);
    }

    [Fact]
    public void Colours_phase_the_colours_in_ascending_order_stay_down_once_potted()
    {
        var ruling = new SnookerShot().Only("yellow", "green", "black").Hit("yellow").Pot("yellow").Judge(Frame with { BallOn = "yellow" });
        Assert.True(ruling.Legal && ruling.Continue);
        Assert.Equal(2, ruling.Points);
        Assert.Empty(ruling.Spot);
        Assert.Equal("green", ruling.Next.BallOn);
        // The green is not on while the yellow is.
        var wrong = new SnookerShot().Only("yellow", "green", "black").Hit("green").Judge(Frame with { BallOn = "yellow" });
        Assert.Equal([Foul.WrongBallFirst], wrong.Fouls);
    }

    [Fact]
    public void Colours_phase_begins_after_the_colour_that_follows_the_last_red_which_is_respotted()
    {
        var ruling = new SnookerShot().Only("yellow", "green", "brown", "blue", "pink", "black").Hit("black").Pot("black").Judge(OnColour("black"));
        Assert.Equal([Id("black")], ruling.Spot);
        Assert.Equal("yellow", ruling.Next.BallOn);
    }

    [Fact]
    public void Respotting_a_colour_goes_to_its_own_spot()
    {
        var table = new Dictionary<BallId, Vec3>();
        SnookerRuleset.Respot(table, [Id("green")], SnookerShot.Table, R);
        Assert.Equal(SnookerTable.Spot(SnookerShot.Table, "green", R), table[Id("green")]);
    }

    [Fact]
    public void Respotting_when_the_own_spot_is_taken_uses_the_highest_value_free_spot()
    {
        var table = new Dictionary<BallId, Vec3> { [Id("red-1")] = SnookerTable.Spot(SnookerShot.Table, "pink", R) };
        SnookerRuleset.Respot(table, [Id("pink")], SnookerShot.Table, R);
        Assert.Equal(SnookerTable.Spot(SnookerShot.Table, "black", R), table[Id("pink")]);
        table = new() { [Id("red-1")] = SnookerTable.Spot(SnookerShot.Table, "pink", R), [Id("red-2")] = SnookerTable.Spot(SnookerShot.Table, "black", R) };
        SnookerRuleset.Respot(table, [Id("pink")], SnookerShot.Table, R);
        Assert.Equal(SnookerTable.Spot(SnookerShot.Table, "blue", R), table[Id("pink")]);
    }

    [Fact]
    public void Respotting_with_every_spot_taken_goes_as_near_its_own_spot_as_it_fits_towards_the_top_cushion()
    {
        var table = BallSet.Colours.Select((c, i) => (Id($"red-{i + 1}"), SnookerTable.Spot(SnookerShot.Table, c, R))).ToDictionary(b => b.Item1, b => b.Item2);
        SnookerRuleset.Respot(table, [Id("brown")], SnookerShot.Table, R);
        var brown = SnookerTable.Spot(SnookerShot.Table, "brown", R);
        Assert.Equal(new Vec3(brown.X + 2 * R, 0, R).X, table[Id("brown")].X, 9);
        Assert.Equal(0, table[Id("brown")].Y);
        // Several at once: the higher value first, so the black takes its spot before the pink looks for one.
        var two = new Dictionary<BallId, Vec3> { [Id("red-1")] = SnookerTable.Spot(SnookerShot.Table, "pink", R) };
        SnookerRuleset.Respot(two, [Id("pink"), Id("black")], SnookerShot.Table, R);
        Assert.Equal(SnookerTable.Spot(SnookerShot.Table, "black", R), two[Id("black")]);
        Assert.Equal(SnookerTable.Spot(SnookerShot.Table, "blue", R), two[Id("pink")]);
    }

    [Fact]
    public void Break_off_is_played_from_in_hand_in_the_D_with_a_red_on()
    {
        var inD = new SnookerShot().Hit("red-5").Judge(Frame with { Shot = 0, Placement = new Vec3(-1.2, 0.1, R) });
        Assert.True(inD.Legal);
        var outside = new SnookerShot().Hit("red-5").Judge(Frame with { Shot = 0, Placement = new Vec3(-0.9, 0.1, R) });
        Assert.Contains(Foul.BadPlacement, outside.Fouls);
        Assert.Equal(BallInHand.D, Ruleset.For(GameRules.Snooker).BreakBallInHand);
        var onColour = new SnookerShot().Hit("brown").Judge(Frame with { Shot = 0 });
        Assert.Contains(Foul.WrongBallFirst, onColour.Fouls);
    }

    [Fact]
    public void Foul_penalty_is_at_least_4_awarded_to_the_opponent()
    {
        var ruling = new SnookerShot().Judge(OnRed);
        Assert.Equal([Foul.NoContact], ruling.Fouls);
        Assert.Equal(4, ruling.Penalty);
        Assert.Equal(new PerPlayer<int>(0, 4), ruling.Next.Score);
        Assert.False(ruling.Continue);
        Assert.Equal(1, ruling.Next.Shooter);
    }

    [Fact]
    public void Foul_penalty_is_the_value_of_the_ball_on()
    {
        var ruling = new SnookerShot().Hit("red-2").Judge(OnColour("black"));
        Assert.Equal(7, ruling.Penalty);
    }

    [Fact]
    public void Foul_penalty_is_the_value_of_the_ball_wrongly_struck_first()
    {
        var ruling = new SnookerShot().Hit("pink").Judge(OnRed);
        Assert.Equal([Foul.WrongBallFirst], ruling.Fouls);
        Assert.Equal(6, ruling.Penalty);
    }

    [Fact]
    public void Foul_penalty_is_the_value_of_a_ball_wrongly_potted()
    {
        var ruling = new SnookerShot().Hit("red-4").Collide("red-4", "blue").Pot("blue").Judge(OnRed);
        Assert.Equal([Foul.WrongBallPotted], ruling.Fouls);
        Assert.Equal(5, ruling.Penalty);
        Assert.Equal(0, ruling.Points);
    }

    [Fact]
    public void In_off_is_a_foul_with_ball_in_hand_in_the_D_for_the_incoming_player()
    {
        var ruling = new SnookerShot().Hit("red-4").Pot("cue").Judge(OnRed);
        Assert.Equal([Foul.CueBallPocketed], ruling.Fouls);
        Assert.Equal(BallInHand.D, ruling.BallInHand);
        Assert.Equal(BallInHand.D, ruling.Next.BallInHand);
        Assert.Equal(4, ruling.Penalty);
    }

    [Fact]
    public void Ball_off_table_is_a_foul()
    {
        var ruling = new SnookerShot().Hit("red-4").Collide("red-4", "black").OffTable("black").Judge(OnRed);
        Assert.Equal([Foul.BallOffTable], ruling.Fouls);
        Assert.Equal(7, ruling.Penalty);
        Assert.Equal([Id("black")], ruling.Spot);
    }

    [Fact]
    public void Jump_shot_over_a_ball_before_the_first_contact_is_a_foul()
    {
        // The cue ball, in the air, passes over the pink to strike a red behind it; on the bed it would have hit the pink.
        var shot = new SnookerShot().At("cue", 0.5, 0).Aim(0).Airborne().Hit("red-1");
        var ruling = shot.Judge(OnRed);
        Assert.Equal([Foul.JumpShot], ruling.Fouls);
        // The same contact without leaving the bed is legal.
        Assert.True(new SnookerShot().At("cue", 0.5, 0).Aim(0).Hit("red-1").Judge(OnRed).Legal);
    }

    [Fact]
    public void Bad_placement_outside_the_D_is_a_foul()
    {
        var ruling = new SnookerShot().Hit("red-1").Judge(Frame with { BallInHand = BallInHand.D, Placement = new Vec3(-1.1, 0.35, R) });
        Assert.Contains(Foul.BadPlacement, ruling.Fouls);
    }

    [Fact]
    public void Reds_potted_on_a_foul_stay_down_and_colours_are_respotted()
    {
        var ruling = new SnookerShot().Hit("red-4").Pot("red-4").Pot("yellow").Pot("cue").Judge(OnRed);
        Assert.False(ruling.Legal);
        Assert.Equal([Id("yellow")], ruling.Spot);
        Assert.Equal(0, ruling.Points);
    }

    [Fact]
    public void There_is_no_rail_rule()
    {
        var ruling = new SnookerShot().Hit("red-4").Judge(OnRed);
        Assert.True(ruling.Legal);
        Assert.False(ruling.Continue);
        Assert.Empty(ruling.Options);
    }

    [Fact]
    public void After_a_foul_the_incoming_player_chooses_play_or_put_back()
    {
        var ruling = new SnookerShot().Hit("red-4").Pot("cue").Judge(OnRed);
        Assert.Equal([RefereeOption.Play, RefereeOption.PutBack], ruling.Options);
        var play = ruling.Choose(RefereeOption.Play);
        Assert.Equal(1, play.Next.Shooter);
        var putBack = ruling.Choose(RefereeOption.PutBack);
        Assert.Equal(0, putBack.Next.Shooter);
        Assert.Equal(BallInHand.D, putBack.Next.BallInHand);
        Assert.Equal(4, putBack.Next.Score.Second);
    }

    [Fact]
    public void Foul_and_a_miss_is_called_when_the_ball_on_is_not_struck_and_offers_replace()
    {
        var ruling = new SnookerShot().Hit("blue").Judge(OnRed);
        Assert.True(ruling.FoulAndMiss);
        Assert.Equal([RefereeOption.Play, RefereeOption.PutBack, RefereeOption.Replace], ruling.Options);
        var replace = ruling.Choose(RefereeOption.Replace);
        Assert.True(replace.Replace);
        Assert.Equal(0, replace.Next.Shooter);
        Assert.Equal(new PerPlayer<int>(0, 5), replace.Next.Score);
        Assert.Equal(new PerPlayer<int>(1, 0), replace.Next.MissesInRow);
        // Striking the ball on and fouling otherwise is no miss.
        Assert.False(new SnookerShot().Hit("red-4").Pot("cue").Judge(OnRed).FoulAndMiss);
    }

    [Fact]
    public void Foul_and_a_miss_is_not_called_when_only_the_black_remains()
    {
        var ruling = new SnookerShot().Only("black").Judge(Frame with { BallOn = "black", Score = new(30, 20) });
        Assert.False(ruling.FoulAndMiss);
    }

    [Fact]
    public void Foul_and_a_miss_is_not_called_when_a_player_needs_snookers()
    {
        // Only pink and black: 13 points remain; 40 behind needs snookers.
        var ruling = new SnookerShot().Only("pink", "black").Hit("black").Judge(Frame with { BallOn = "pink", Score = new(10, 50) });
        Assert.False(ruling.FoulAndMiss);
        // 40 behind 50 needs no snookers before, but after the 7 away it does: no miss either.
        Assert.False(new SnookerShot().Only("pink", "black").Hit("black").Judge(Frame with { BallOn = "pink", Score = new(40, 50) }).FoulAndMiss);
        var level = new SnookerShot().Only("pink", "black").Hit("black").Judge(Frame with { BallOn = "pink", Score = new(45, 50) });
        Assert.True(level.FoulAndMiss);
    }

    [Fact]
    public void Foul_and_a_miss_is_not_called_when_the_striker_was_snookered_and_the_cue_ball_reached_the_ball_ons_distance()
    {
        // The pink stands between the cue ball and the last red: no part of the red can be struck.
        var snookered = new SnookerShot().Only("red-1", "pink", "black").At("cue", 0, 0.3).At("pink", 0.3, 0.3).At("red-1", 0.6, 0.3);
        var reached = snookered.Hit("pink").Rests("cue", -0.7, 0.3).Judge(OnRed);
        Assert.False(reached.FoulAndMiss);
        var shortOf = new SnookerShot().Only("red-1", "pink", "black").At("cue", 0, 0.3).At("pink", 0.3, 0.3).At("red-1", 0.6, 0.3)
            .Hit("pink").Rests("cue", 0.1, 0.3).Judge(OnRed);
        Assert.True(shortOf.FoulAndMiss);
    }

    [Fact]
    public void Three_misses_with_a_full_ball_view_lose_the_frame_and_the_referee_warns_after_the_second()
    {
        // A clear view of the last red (on the rack's apex) past the blue.
        var second = Clear().Hit("blue").Judge(OnRed with { MissesInRow = new(1, 0) });
        Assert.True(second.FoulAndMiss);
        Assert.Contains("Warning", second.Message, StringComparison.Ordinal);
        Assert.False(second.GameOver);
        var third = Clear().Hit("blue").Judge(OnRed with { MissesInRow = new(2, 0) });
        Assert.Contains(Foul.ThreeMisses, third.Fouls);
        Assert.True(third.GameOver);
        Assert.Equal(1, third.Winner);
        // Without a full ball view (snookered, the cue ball short of the red) the count goes on and loses nothing.
        var blind = new SnookerShot().Only("red-1", "pink", "black").At("cue", 0, 0.3).At("pink", 0.3, 0.3).At("red-1", 0.6, 0.3)
            .Hit("pink").Judge(OnRed with { MissesInRow = new(2, 0) });
        Assert.True(blind.FoulAndMiss);
        Assert.False(blind.GameOver);
    }

    [Fact]
    public void Free_ball_is_offered_after_a_foul_when_the_incoming_player_is_snookered()
    {
        var ruling = new SnookerShot().Only("red-1", "pink", "black").At("cue", 0, 0.3).At("pink", 0.3, 0.3).At("red-1", 0.6, 0.3)
            .Hit("black").Judge(OnRed with { Shooter = 1 });
        Assert.True(ruling.FreeBall);
        Assert.True(ruling.Next.FreeBall);
        Assert.False(ruling.Choose(RefereeOption.PutBack).Next.FreeBall);
        // Not snookered, no free ball.
        Assert.False(Clear().Hit("black").Judge(OnRed with { Shooter = 1 }).FreeBall);
    }

    [Fact]
    public void Free_ball_nominated_and_potted_scores_as_the_ball_on_and_is_respotted()
    {
        var state = OnRed with { FreeBall = true, Call = Call.Nominate(Id("pink")) };
        var ruling = new SnookerShot().Only("red-1", "pink", "black").Hit("pink").Pot("pink").Judge(state);
        Assert.True(ruling.Legal && ruling.Continue);
        Assert.Equal(1, ruling.Points);
        Assert.Equal([Id("pink")], ruling.Spot);
        Assert.Equal("colour", ruling.Next.BallOn);
        // In the colours phase it scores the colour on's value.
        var colours = new SnookerShot().Only("green", "pink", "black").Hit("pink").Pot("pink")
            .Judge(Frame with { BallOn = "green", FreeBall = true, Call = Call.Nominate(Id("pink")) });
        Assert.Equal(3, colours.Points);
        Assert.Equal([Id("pink")], colours.Spot);
        Assert.Equal("green", colours.Next.BallOn);
        // Struck first, it is the ball on; the real ball on struck first is not.
        var wrong = new SnookerShot().Only("red-1", "pink", "black").Hit("red-1").Judge(state);
        Assert.Contains(Foul.WrongBallFirst, wrong.Fouls);
    }

    [Fact]
    public void Snookering_the_opponent_behind_the_free_ball_is_a_foul()
    {
        // The free ball (pink) ends between the cue ball and the last red.
        var state = OnRed with { FreeBall = true, Call = Call.Nominate(Id("pink")) };
        var ruling = new SnookerShot().Only("red-1", "pink", "black").At("cue", 0, 0.3).At("pink", 0.5, 0.6).At("red-1", 0.6, 0.3)
            .Hit("pink").Rests("pink", 0.3, 0.3).Judge(state);
        Assert.Contains(Foul.SnookeredByFreeBall, ruling.Fouls);
        Assert.Equal(4, ruling.Penalty);
        // Unless only the pink and black remain.
        var late = new SnookerShot().Only("pink", "black").At("cue", 0, 0.3).At("black", 0.6, 0.3).At("pink", 0.5, 0.6)
            .Hit("black").Rests("black", 0.3, 0.3).Judge(Frame with { BallOn = "pink", FreeBall = true, Call = Call.Nominate(Id("black")) });
        Assert.DoesNotContain(Foul.SnookeredByFreeBall, late.Fouls);
    }

    [Fact]
    public void End_of_frame_the_last_black_potted_gives_the_frame_to_the_higher_score()
    {
        var ruling = new SnookerShot().Only("black").Hit("black").Pot("black").Judge(Frame with { BallOn = "black", Score = new(40, 44) });
        Assert.True(ruling.GameOver);
        Assert.Equal(0, ruling.Winner);
        Assert.Equal(7, ruling.Points);
        // A foul on the last black ends it too.
        var foul = new SnookerShot().Only("black").Hit("black").Pot("cue").Judge(Frame with { BallOn = "black", Score = new(40, 44) });
        Assert.True(foul.GameOver);
        Assert.Equal(1, foul.Winner);
    }

    [Fact]
    public void End_of_frame_on_equal_scores_the_black_is_respotted_and_played_from_in_hand_in_the_D()
    {
        var ruling = new SnookerShot().Only("black").Hit("black").Pot("black").Judge(Frame with { BallOn = "black", Score = new(40, 47) });
        Assert.False(ruling.GameOver);
        Assert.Equal([Id("black")], ruling.Spot);
        Assert.Equal(BallInHand.D, ruling.Next.BallInHand);
        Assert.Equal("black", ruling.Next.BallOn);
        Assert.Equal(new PerPlayer<int>(47, 47), ruling.Next.Score);
        // The first to score then decides it.
        var decider = new SnookerShot().Only("black").Hit("black").Pot("black").Judge(ruling.Next);
        Assert.True(decider.GameOver);
        Assert.Equal(ruling.Next.Shooter, decider.Winner);
    }
}
