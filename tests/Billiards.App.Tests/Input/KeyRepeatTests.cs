using Billiards.App.Game;
using Billiards.App.Input;
using Billiards.App.Platform;
using Billiards.App.Tests.Game;
using Billiards.Core.Rules;

namespace Billiards.App.Tests.Input;

public class KeyRepeatTests
{
    // The repeats of one key held from 0 to `until` seconds, polled every `frame` seconds.
    private static List<double> Repeats(Key key, double until, double frame)
    {
        var repeat = new KeyRepeat();
        var times = new List<double>();
        repeat.Down(key, 0);
        for (double now = 0; now <= until + 1e-9; now += frame)
        {
            repeat.Due(now, (k, t) =>
            {
                Assert.Equal(key, k);
                times.Add(t);
            });
        }
        return times;
    }

    [Fact]
    public void AHeldKeyRepeatsAfterTheDelayAndSpeedsUpToTheTopRate()
    {
        var times = Repeats(Key.Left, 3, 1.0 / 60);
        Assert.Equal(KeyRepeat.Delay, times[0], 12);
        Assert.Equal(KeyRepeat.Delay + (1 / KeyRepeat.StartRate), times[1], 12);
        var gaps = times.Zip(times.Skip(1), (a, b) => b - a).ToList();
        Assert.All(gaps.Zip(gaps.Skip(1)), g => Assert.True(g.Second <= g.First + 1e-12));
        Assert.Equal(1 / KeyRepeat.TopRate, gaps[^1], 12);
        // Between the delay and the end of the ramp the count is about the mean rate's: 1.2 s at 25/s.
        int ramp = times.Count(t => t < KeyRepeat.Delay + KeyRepeat.RampSeconds);
        Assert.InRange(ramp, 27, 32);
    }

    [Fact]
    public void TheRepeatsFallAtTheSameTimesAtAnyFrameRate()
    {
        var at60 = Repeats(Key.W, 2, 1.0 / 60);
        Assert.Equal(at60, Repeats(Key.W, 2, 1.0 / 144));
        Assert.Equal(at60, Repeats(Key.W, 2, 0.25));
    }

    // Presses of Left (the first and its repeats) through the router, for a key held from 0 to
    // 1 s and frames `frame` seconds apart; the release comes at the start of the frame after it.
    private static int HeldLeftPresses(double frame)
    {
        var window = new FakeWindow();
        var clock = new ManualClock();
        int presses = 0;
        using var router = new InputRouter(window, clock, e => presses += e is KeyInput { Pressed: true, Key: Key.Left } ? 1 : 0);
        window.Hold(Key.Left);
        while (clock.Now < 1 - 1e-9)
        {
            clock.Now = Math.Min(1, clock.Now + frame);
            if (clock.Now >= 1 - 1e-9)
            {
                break;
            }
            router.Repeat();
        }
        // As a script raises it: at the start of the frame, before the frame's repeats.
        window.Release(Key.Left);
        router.Repeat();
        return presses;
    }

    [Fact]
    public void AKeyHeldRepeatsAsOftenWhetherItsReleaseComesInTheFrameOfItsLastRepeatsOrFramesLater()
    {
        // The press and every repeat due before 1 s at 60 FPS, and as many when the release comes frames late.
        int at60 = HeldLeftPresses(1.0 / 60);
        Assert.Equal(1 + KeyRepeatTimesBefore(1), at60);
        Assert.Equal(at60, HeldLeftPresses(0.3));
        Assert.Equal(at60, HeldLeftPresses(1));
    }

    private static int KeyRepeatTimesBefore(double until) => Repeats(Key.Left, until - 1e-9, 1e-3).Count;

    [Fact]
    public void KeysThatDoNotStepAValueNeverRepeatAndAReleasedKeyStops()
    {
        Assert.Empty(Repeats(Key.Space, 3, 0.1));
        Assert.Empty(Repeats(Key.G, 3, 0.1));
        var repeat = new KeyRepeat();
        repeat.Down(Key.Right, 0);
        int n = 0;
        repeat.Due(0.5, (_, _) => n++);
        repeat.Up(Key.Right);
        repeat.Due(5, (_, _) => n++);
        Assert.Equal(2, n); // 0.35 and 0.45 s
    }
}

public class HeldKeyTests
{
    private static MatchNode Match(TestGame game) => game.World.Tree.Root.GetInTree<MatchNode>();

    private static TestGame Game() =>
        new(TestScenes.TwoBalls(), new MatchSetup(Billiards.Core.Rules.GameRules.EightBall, [new Seat("Anna"), new Seat("Ben")]));

    [Fact]
    public void HoldingTheAimKeyTurnsTheCueOnceThenByEveryRepeat()
    {
        using var game = Game();
        var match = Match(game);
        game.Frame();
        double start = match.AimDegrees;
        game.Window.Hold(Key.Left);
        for (int i = 0; i < 120; i++)
        {
            game.Frame(1.0 / 60);    // 2 s held
        }
        game.Window.Release(Key.Left);
        game.Frame(1.0 / 60);
        double turned = Math.IEEERemainder(match.AimDegrees - start, 360);
        var repeat = new KeyRepeat();
        repeat.Down(Key.Left, 0);
        int repeats = 0;
        repeat.Due(2.0 + 1e-9, (_, _) => repeats++);
        Assert.True(repeats > 40, $"{repeats} repeats");
        Assert.Equal((1 + repeats) * MatchNode.AimStepDegrees, turned, 6);
        // Released: nothing more.
        for (int i = 0; i < 30; i++)
        {
            game.Frame(1.0 / 60);
        }
        Assert.Equal(turned, Math.IEEERemainder(match.AimDegrees - start, 360), 9);
    }

    [Fact]
    public void HoldingPowerUpGoesFrom3To8MetresASecondInUnderTwoSeconds()
    {
        using var game = Game();
        var match = Match(game);
        game.Frame();
        Assert.Equal(3, match.Power);
        game.Window.Hold(Key.W);
        double held = 0;
        while (match.Power < MatchNode.MaxPower && held < 5)
        {
            game.Frame(1.0 / 60);
            held += 1.0 / 60;
        }
        game.Window.Release(Key.W);
        Assert.Equal(MatchNode.MaxPower, match.Power);
        Assert.InRange(held, 0.5, 1.5);
    }

    [Fact]
    public void ShiftMakesTheArrowKeysAndTheMouseOrbitFine()
    {
        using var game = Game();
        var match = Match(game);
        var camera = game.World.Tree.Root.GetInTree<Billiards.App.Camera.CameraNode>().Camera;
        game.Frame();
        double a0 = match.AimDegrees;
        game.Window.Hold(Key.Shift);
        game.Window.Press(Key.Left);
        game.Frame();
        Assert.Equal(MatchNode.FineAimStepDegrees, Math.IEEERemainder(match.AimDegrees - a0, 360), 9);

        // A 100 px drag in view mode with Shift turns a tenth of what it turns without.
        double Drag()
        {
            double phi = camera.Phi;
            game.Window.MoveTo(400, 300);
            game.Window.Down();
            game.Window.MoveTo(500, 300);
            game.Window.Up();
            game.Frame();
            return camera.Phi - phi;
        }
        double fine = Drag();
        game.Window.Release(Key.Shift);
        double coarse = Drag();
        Assert.NotEqual(0, coarse);
        Assert.Equal(coarse * Billiards.App.Input.Modes.SeedControls.FineOrbitFactor, fine, 9);
    }
}
