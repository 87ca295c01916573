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
        Assert.Equal(CushionId.FootLeftJaw, CushionIds.Jaw(PocketId.FootLeft));
        Assert.Equal(CushionId.SideRightBack, CushionIds.Back(PocketId.SideRight));
        foreach (var pocket in PocketIds.All)
        {
            Assert.Equal(pocket, CushionIds.Jaw(pocket).PocketOf());
            Assert.Equal(pocket, CushionIds.Back(pocket).PocketOf());
            Assert.False(CushionIds.Jaw(pocket).IsRail());
        }
        Assert.True(CushionId.RightFoot.IsRail());
        Assert.Equal(PocketId.None, CushionId.Head.PocketOf());
        Assert.Equal("side-left-jaw", CushionId.SideLeftJaw.ToName());
        Assert.Equal("foot-right-back", CushionId.FootRightBack.ToName());
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
            if (id.IsRail())
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
    [InlineData("standard", 0.0, CushionId.Foot)]
    [InlineData("thesis", 0.0, CushionId.Foot)]
    [InlineData("standard", 180.0, CushionId.Head)]
    [InlineData("thesis", 180.0, CushionId.Head)]
    [InlineData("standard", 90.0, CushionId.LeftFoot)]
    [InlineData("thesis", 90.0, CushionId.LeftFoot)]
    [InlineData("standard", -90.0, CushionId.RightHead)]
    [InlineData("thesis", -90.0, CushionId.RightHead)]
    public void AStraightShotAtARailHitsTheSameCushionUnderBothModels(string model, double aim, CushionId expected)
    {
        // From a point off the side pockets (x = +0.3 or -0.3 towards the named long rail's half).
        double x = expected is CushionId.LeftFoot ? 0.3 : expected is CushionId.RightHead ? -0.3 : 0;
        var sim = Create(model, $$""" "balls": [ { "id": "cue", "position": [{{x.ToString(System.Globalization.CultureInfo.InvariantCulture)}}, 0.1] } ] """);
        sim.Strike(new ShotSpec(1.5, aim));
        sim.AdvanceTo(30);
        var first = sim.Events.AsSpan().ToArray().First(e => e.Kind == EventKind.BallCushion);
        Assert.Equal(expected, sim.Cushion(first));
        Assert.Equal(CushionId.None, sim.Cushion(sim.Events[0]));
    }
}
