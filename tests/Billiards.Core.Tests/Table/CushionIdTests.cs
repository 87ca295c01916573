using Billiards.Core.Cue;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Table;

/// <summary>Cushion identities are typed and mean the same under both models.</summary>
public class CushionIdTests
{
    private static Simulation Create(string model, string ballsAndShot) => SimulationFactory.Create(SceneLoader.Parse($$"""
        { "format": "billiards-scene/1", "table": { "preset": "pool-9ft" }, "physics": { "model": "{{model}}" }, {{ballsAndShot}} }
        """, "cushions.json"));

    [Fact]
    public void JawsAndBacksBelongToTheirPocketAndRailsToNone()
    {
        Assert.Equal(CushionKind.Jaw, CushionId.Jaw(PoolPockets.FootLeft).Kind);
        Assert.Equal(CushionKind.Back, CushionId.Back(PoolPockets.SideRight).Kind);
        Assert.NotEqual(CushionId.Jaw(PoolPockets.FootLeft), CushionId.Jaw(PoolPockets.FootRight));
        foreach (var pocket in PoolPockets.All)
        {
            Assert.Equal(pocket, CushionId.Jaw(pocket).Pocket);
            Assert.Equal(pocket, CushionId.Back(pocket).Pocket);
            Assert.False(CushionId.Jaw(pocket).IsRail);
        }
        Assert.True(CushionId.RightFoot.IsRail);
        Assert.Equal(PocketId.None, CushionId.Head.Pocket);
        Assert.Equal(CushionId.None, CushionId.Jaw(PocketId.None));
        Assert.Equal("side-left-jaw", CushionId.Jaw(PoolPockets.SideLeft).ToName());
        Assert.Equal("foot-right-back", CushionId.Back(PoolPockets.FootRight).ToName());
        Assert.Equal("left-foot", CushionId.LeftFoot.ToName());
    }

    [Theory]
    [InlineData("standard")]
    [InlineData("thesis")]
    public void EveryFeatureOfAModelIsTheCushionItsResultNameSays(string model)
    {
        var sim = Create(model, """ "balls": [ { "id": "cue", "position": [0, 0] } ] """);
        int features = 0;
        for (int f = 0; f < 64; f++)
        {
            var id = sim.CushionOf(f);
            if (id == CushionId.None)
            {
                continue;
            }
            features++;
            string name = sim.FeatureName(EventKind.BallCushion, f);
            // Rails carry the same name under both models; a jaw's name starts with its pocket's
            // jaw ("foot-left-jaw", or "foot-left-jaw-foot" for the standard model's jaw on the foot rail).
            if (id.IsRail)
            {
                Assert.Equal(id.ToName(), name);
            }
            else
            {
                Assert.StartsWith(id.ToName(), name);
            }
        }
        // Standard: 6 rails and two jaws per pocket; thesis: 6 rails, a jaw and a back per pocket.
        Assert.Equal(18, features);
    }

    [Theory]
    [InlineData("standard", 0.0, "foot")]
    [InlineData("thesis", 0.0, "foot")]
    [InlineData("standard", 180.0, "head")]
    [InlineData("thesis", 180.0, "head")]
    [InlineData("standard", 90.0, "left-foot")]
    [InlineData("thesis", 90.0, "left-foot")]
    [InlineData("standard", -90.0, "right-head")]
    [InlineData("thesis", -90.0, "right-head")]
    public void AStraightShotAtARailHitsTheSameCushionUnderBothModels(string model, double aim, string rail)
    {
        var expected = CushionId.OfRail(CushionId.RailNames.ToList().IndexOf(rail));
        // From a point off the side pockets (x = +0.3 or -0.3 towards the named long rail's half).
        double x = expected == CushionId.LeftFoot ? 0.3 : expected == CushionId.RightHead ? -0.3 : 0;
        var sim = Create(model, $$""" "balls": [ { "id": "cue", "position": [{{x.ToString(System.Globalization.CultureInfo.InvariantCulture)}}, 0.1] } ] """);
        sim.Strike(new ShotSpec(1.5, aim));
        sim.AdvanceTo(30);
        var first = sim.Events.AsSpan().ToArray().First(e => e.Kind == EventKind.BallCushion);
        Assert.Equal(expected, sim.Cushion(first));
        Assert.Equal(CushionId.None, sim.Cushion(sim.Events[0]));
    }
}
