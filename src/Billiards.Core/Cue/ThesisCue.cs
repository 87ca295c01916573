namespace Billiards.Core.Cue;

/// <summary>
/// The cue of the thesis model, the thesis's <c>Queue</c> (German for the cue; seed 4.1.5, 4.4.3,
/// 4.4.4), named so that it does not shadow <see cref="Queue{T}"/>; the thesis engine's property
/// keeps the thesis's name (<see cref="Physics.Thesis.PhysicsEngine.Queue"/>). In the seed's
/// units. It holds the tip displacement from the cue ball's centre (<see cref="EX"/> sideways, <see cref="EY"/> up: the effet, which the
/// physics engine reads and decays after each collision), and the elevation (drawing only).
/// </summary>
public sealed class ThesisCue
{
    /// <summary>The ball radius (cm): the tip displacement is kept within it so the tip stays on the ball.</summary>
    public const float BallRadius = Physics.Thesis.PhysicsEngine.BallRadius;

    /// <summary>The stroke speed cap of Formel 31 (cm/s): the fastest cue.</summary>
    public const float MaxStrokeSpeed = 800f;

    /// <summary>The constant of Formel 31 that turns mouse travel per millisecond into cm/s.</summary>
    public const float StrokeScale = 250f;

    /// <summary>Sideways tip displacement e_x (cm), positive to the right seen from behind the cue; bends cushion rebounds (Formel 24).</summary>
    public float EX { get; set; }

    /// <summary>Vertical tip displacement e_y (cm), positive above centre; follow or draw at the first ball contact (Formel 19).</summary>
    public float EY { get; set; }

    /// <summary>Cue elevation (deg above the bed). The seed draws it but the strike ignores it (seed 4.5.3).</summary>
    public float Grade { get; set; }

    /// <summary>
    /// The strike speed of Formel 31, s = d / t * 250, capped at 800.
    /// </summary>
    /// <remarks>
    /// The seed measures the stroke with the mouse (d, pixels of forward travel) and GLUT's clock
    /// (t, milliseconds), and uses s as the cue ball's speed in cm/s. Here s is the cue's speed
    /// at impact, what <see cref="ShotSpec.Speed"/> means for every model (after division by
    /// 100); the thesis model turns it into the ball's speed with
    /// <see cref="Physics.Thesis.ThesisSimulation.CueToBallSpeed"/>. A stroke of 100 px in
    /// 50 ms thus gives 500 cm/s. A zero or negative time counts as infinitely fast (the cap);
    /// a stroke that did not move forward gives 0.
    /// </remarks>
    /// <param name="distance">Forward mouse travel d (pixels).</param>
    /// <param name="milliseconds">Time t the forward travel took (ms).</param>
    /// <returns>The cue's speed (cm/s), in [0, 800].</returns>
    public static float StrokeSpeed(float distance, float milliseconds)
    {
        if (distance <= 0)
        {
            return 0;
        }
        if (milliseconds <= 0)
        {
            return MaxStrokeSpeed;
        }
        return MathF.Min(distance / milliseconds * StrokeScale, MaxStrokeSpeed);
    }

    /// <summary>Back to the start of a shot: tip centred, cue level.</summary>
    public void Reset()
    {
        EX = 0;
        EY = 0;
        Grade = 0;
    }
}
