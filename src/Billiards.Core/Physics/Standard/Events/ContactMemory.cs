namespace Billiards.Core.Physics.Standard.Events;

/// <summary>
/// The TC model's memory (McNamara and Luding 1998): each ball's last contact partner (a ball
/// index, or the ball count plus a cushion feature) and when it happened, so that a contact of the
/// same two bodies within <see cref="EventEngine.ContactDuration"/> is known as a repeat.
/// </summary>
internal sealed class ContactMemory
{
    private readonly int[] _lastPartner;
    private readonly double[] _lastContactTime;

    /// <summary>A memory for <paramref name="n"/> balls that remembers nothing yet.</summary>
    public ContactMemory(int n)
    {
        _lastPartner = new int[n];
        _lastContactTime = new double[n];
        Forget();
    }

    /// <summary>True when ball's last contact was with partner less than a contact duration before <paramref name="time"/>.</summary>
    public bool IsRepeat(int ball, int partner, double time) =>
        _lastPartner[ball] == partner && time - _lastContactTime[ball] < EventEngine.ContactDuration;

    /// <summary>Records a contact of ball with partner at <paramref name="time"/> (s).</summary>
    public void Remember(int ball, int partner, double time)
    {
        _lastPartner[ball] = partner;
        _lastContactTime[ball] = time;
    }

    /// <summary>Forgets every contact.</summary>
    public void Forget()
    {
        _lastPartner.AsSpan().Fill(-1);
        _lastContactTime.AsSpan().Fill(double.NegativeInfinity);
    }

    /// <summary>Copies another memory (same ball count).</summary>
    public void CopyFrom(ContactMemory other)
    {
        other._lastPartner.CopyTo(_lastPartner, 0);
        other._lastContactTime.CopyTo(_lastContactTime, 0);
    }
}
