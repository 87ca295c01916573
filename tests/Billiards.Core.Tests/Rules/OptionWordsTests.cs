using Billiards.Core.Rules;

namespace Billiards.Core.Tests.Rules;

/// <summary>Each game words and parses its own options (<see cref="Ruleset.OptionWords"/>); no shared list names them.</summary>
public class OptionWordsTests
{
    public static TheoryData<string> Games => new(Ruleset.All.Select(r => r.Name));

    [Theory]
    [MemberData(nameof(Games))]
    public void EveryOptionOfAGameParsesBackFromItsWordAndNoWordIsUsedTwice(string game)
    {
        var ruleset = Ruleset.For(game);
        Assert.Equal(ruleset.OptionWords.Count, ruleset.OptionWords.Select(o => o.Word).Distinct().Count());
        foreach (var (option, word) in ruleset.OptionWords)
        {
            Assert.Equal(word, ruleset.WordOf(option));
            Assert.True(ruleset.TryParseOption(word, out var parsed));
            Assert.Equal(option, parsed);
            Assert.Equal(word, option.ToName());
        }
    }

    [Fact]
    public void AGameParsesOnlyItsOwnOptions()
    {
        var eight = Ruleset.For(GameRules.EightBall);
        Assert.False(eight.TryParseOption("pass-back", out _));
        Assert.False(eight.TryWordOf(RefereeOption.PutBack, out _));
        Assert.Throws<ArgumentOutOfRangeException>(() => eight.WordOf(RefereeOption.Shoot));
        Assert.True(Ruleset.For(GameRules.NineBall).TryParseOption("pass-back", out var pass));
        Assert.Equal(RefereeOption.PassBack, pass);
        Assert.Equal(
            [RefereeOption.Accept, RefereeOption.SpotBreak],
            Ruleset.For(ThreeCushionRuleset.ThreeCushion).OptionWords.Select(o => o.Option));
    }

    [Fact]
    public void TheWordsOfEveryOptionAreTheContracts()
    {
        // scene-format.md: accept, rerack, spot-eight, shoot, pass-back; play, put-back, replace; spot-break.
        var words = Ruleset.All.SelectMany(r => r.OptionWords).Select(o => o.Word).Distinct().Order().ToList();
        Assert.Equal(["accept", "pass-back", "play", "put-back", "replace", "rerack", "shoot", "spot-break", "spot-eight"], words);
        Assert.All(Enum.GetValues<RefereeOption>(), o => Assert.True(RuleNames.TryParseOption(o.ToName(), out var back) && back == o));
    }
}
