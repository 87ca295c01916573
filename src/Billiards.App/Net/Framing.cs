using System.Buffers.Binary;

namespace Billiards.App.Net;

/// <summary>
/// The wire's frames: a 4-byte big-endian length, then that many bytes of one message's UTF-8
/// JSON, 1 to <see cref="MaxMessageBytes"/>. A frame once begun must arrive whole within its
/// deadline (a slow drip or a truncated frame closes the connection); the wait for the next
/// frame's first byte is the silent peer's timeout.
/// </summary>
public static class Framing
{
    /// <summary>Largest message (bytes of JSON).</summary>
    public const int MaxMessageBytes = 64 * 1024;

    /// <summary>The frame of <paramref name="json"/>.</summary>
    /// <exception cref="ArgumentException">Empty or over <see cref="MaxMessageBytes"/>.</exception>
    public static byte[] Frame(ReadOnlySpan<byte> json)
    {
        if (json.Length is 0 or > MaxMessageBytes)
        {
            throw new ArgumentException($"a message is 1 to {MaxMessageBytes} bytes, not {json.Length}", nameof(json));
        }
        var frame = new byte[4 + json.Length];
        BinaryPrimitives.WriteUInt32BigEndian(frame, (uint)json.Length);
        json.CopyTo(frame.AsSpan(4));
        return frame;
    }

    /// <summary>
    /// Reads one frame's message from <paramref name="stream"/>: null at a clean end of stream
    /// before a frame begins. The first byte may take <paramref name="idle"/>, the rest of the
    /// frame <paramref name="frameDeadline"/> from its first byte.
    /// </summary>
    /// <exception cref="ProtocolException">A length of 0 or over the limit, a frame cut off, a frame not whole by its deadline, or no frame within <paramref name="idle"/>.</exception>
    public static async Task<byte[]?> ReadAsync(Stream stream, TimeSpan idle, TimeSpan frameDeadline, CancellationToken cancel)
    {
        ArgumentNullException.ThrowIfNull(stream);
        var header = new byte[4];
        using (var first = CancellationTokenSource.CreateLinkedTokenSource(cancel))
        {
            first.CancelAfter(idle);
            int n;
            try
            {
                n = await stream.ReadAsync(header.AsMemory(0, 1), first.Token).ConfigureAwait(false);
            }
            catch (OperationCanceledException) when (!cancel.IsCancellationRequested)
            {
                throw new ProtocolException($"silent peer: nothing received for {idle.TotalSeconds:0} s");
            }
            if (n == 0)
            {
                return null;
            }
        }
        using var rest = CancellationTokenSource.CreateLinkedTokenSource(cancel);
        rest.CancelAfter(frameDeadline);
        try
        {
            await ReadExactly(stream, header.AsMemory(1, 3), "frame header", rest.Token).ConfigureAwait(false);
            uint length = BinaryPrimitives.ReadUInt32BigEndian(header);
            if (length is 0 or > MaxMessageBytes)
            {
                throw new ProtocolException($"frame of {length} bytes (a message is 1 to {MaxMessageBytes} bytes)");
            }
            var body = new byte[length];
            await ReadExactly(stream, body, $"frame of {length} bytes", rest.Token).ConfigureAwait(false);
            return body;
        }
        catch (OperationCanceledException) when (!cancel.IsCancellationRequested)
        {
            throw new ProtocolException($"slow frame: not whole within {frameDeadline.TotalSeconds:0.#} s of its first byte");
        }
    }

    private static async Task ReadExactly(Stream stream, Memory<byte> buffer, string what, CancellationToken cancel)
    {
        int read = 0;
        while (read < buffer.Length)
        {
            int n = await stream.ReadAsync(buffer[read..], cancel).ConfigureAwait(false);
            if (n == 0)
            {
                throw new ProtocolException($"truncated {what}: the connection closed after {read} of {buffer.Length} bytes");
            }
            read += n;
        }
    }
}
