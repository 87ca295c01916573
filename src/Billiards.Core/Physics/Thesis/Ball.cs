using System.Numerics;

namespace Billiards.Core.Physics.Thesis;

/// <summary>
/// One ball of the thesis model (seed 4.1.1), in the seed's frame and units: centimetres,
/// cm/s, Y up, the bed in the XZ plane, origin at the centre of the table; single precision
/// like the seed's <c>Vec3D</c>.
/// </summary>
/// <remarks>
/// The seed has one "pocketed" flag that hides the ball once it has fallen below
/// y = -20 cm. A ball that the pocket test has caught but that is still falling needs its own
/// mark too (it must keep falling, and the shot must not end meanwhile): that is
/// <see cref="Pocket"/>, set when the pocket test fires, while <see cref="IsPocketed"/> follows the
/// seed's flag and takes the ball out of play.
/// </remarks>
public sealed class Ball
{
    /// <summary>Mass of every ball (kg): the seed's 170 g, used by the pocket drop (Listing 4).</summary>
    public const float Mass = 0.17f;

    /// <summary>Creates ball <paramref name="number"/> at rest at <paramref name="position"/> (cm).</summary>
    public Ball(int number, Vector3 position)
    {
        Number = number;
        Position = position;
    }

    /// <summary>The ball's id value in its set.</summary>
    public int Number { get; }

    /// <summary>True for a cue ball of the set, the only ball the effet acts on (seed 4.3.2).</summary>
    public bool IsCue { get; init; }

    /// <summary>Centre of the ball (cm); y = 2.86 while it lies on the bed.</summary>
    public Vector3 Position { get; set; }

    /// <summary>Velocity of the centre (cm/s); y is non-zero only while the ball drops into a pocket.</summary>
    public Vector3 Velocity { get; set; }

    /// <summary>Orientation for drawing (seed Listing 1); only integrated when asked for.</summary>
    public Quaternion Orientation { get; set; } = Quaternion.Identity;

    /// <summary>Index of the pocket the ball is dropping into or lies in (in the table's <see cref="Table.TableSpec.Pockets"/>), or -1.</summary>
    public int Pocket { get; set; } = -1;

    /// <summary>The seed's pocketed flag: set once the ball has fallen below y = -20 cm; it is then out of play and not drawn.</summary>
    public bool IsPocketed { get; set; }

    /// <summary>True while the ball lies on the bed: neither dropping nor pocketed (nor taken out of play by hand).</summary>
    public bool IsOnBed => Pocket < 0 && !IsPocketed;

    /// <summary>
    /// A random orientation (seed 4.1.1): a quaternion from four random numbers, normalised.
    /// </summary>
    /// <remarks>
    /// The seed does not say which range its random numbers have; we draw each from [-1, 1) so
    /// that every rotation can come out (four numbers from [0, 1) would only ever give one
    /// eighth of them). A draw too close to zero to normalise is drawn again.
    /// </remarks>
    public void RandomizeOrientation(Random random)
    {
        Quaternion q;
        do
        {
            q = new Quaternion(Next(random), Next(random), Next(random), Next(random));
        }
        while (q.LengthSquared() < 1e-6f);
        Orientation = Quaternion.Normalize(q);

        static float Next(Random random) => random.NextSingle() * 2 - 1;
    }
}
