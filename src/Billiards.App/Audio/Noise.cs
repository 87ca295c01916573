namespace Billiards.App.Audio;

/// <summary>
/// A small seeded white-noise source (xorshift32): the same seed gives the same samples on every
/// machine, which keeps offline renders bit for bit reproducible.
/// </summary>
public struct Noise
{
    private uint _state;

    /// <summary>Starts the sequence of a seed (0 is replaced, xorshift would stay at 0).</summary>
    public Noise(uint seed) => _state = Mix(seed) is var s and not 0 ? s : 0x9E3779B9u;

    /// <summary>Next sample, uniform in [-1, 1).</summary>
    public float Next()
    {
        uint x = _state;
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        _state = x;
        return (int)x * (1f / 2147483648f);
    }

    /// <summary>A uniform number in [-1, 1) for a variation, from the same sequence.</summary>
    public double Vary() => Next();

    /// <summary>Scrambles a seed (the finaliser of MurmurHash3), so neighbouring seeds give unrelated sequences.</summary>
    public static uint Mix(uint h)
    {
        h ^= h >> 16;
        h *= 0x85EBCA6Bu;
        h ^= h >> 13;
        h *= 0xC2B2AE35u;
        h ^= h >> 16;
        return h;
    }
}
