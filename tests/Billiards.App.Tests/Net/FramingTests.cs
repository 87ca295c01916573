using System.Buffers.Binary;
using Billiards.App.Net;

namespace Billiards.App.Tests.Net;

/// <summary>Frames: a 4-byte length and at most 64 KB; a bad length, a cut-off frame and a slow drip are refused.</summary>
public class FramingTests
{
    private static readonly TimeSpan Long = TimeSpan.FromSeconds(5);

    private static Task<byte[]?> Read(Stream s, TimeSpan? frame = null) => Framing.ReadAsync(s, Long, frame ?? Long, CancellationToken.None);

    [Fact]
    public async Task AFrameReadsBackItsMessageAndACleanEndIsNull()
    {
        byte[] json = MessageCodec.Write(new Ping(1, false));
        using var s = new MemoryStream([.. Framing.Frame(json), .. Framing.Frame(json)]);
        Assert.Equal(json, await Read(s));
        Assert.Equal(json, await Read(s));
        Assert.Null(await Read(s));
    }

    [Fact]
    public void AFrameIsOneTo64KBytes()
    {
        Assert.Throws<ArgumentException>(() => Framing.Frame([]));
        Assert.Throws<ArgumentException>(() => Framing.Frame(new byte[Framing.MaxMessageBytes + 1]));
        var frame = Framing.Frame(new byte[Framing.MaxMessageBytes]);
        Assert.Equal((uint)Framing.MaxMessageBytes, BinaryPrimitives.ReadUInt32BigEndian(frame));
    }

    [Theory]
    [InlineData(0u, "frame of 0 bytes")]
    [InlineData(65537u, "frame of 65537 bytes")]
    [InlineData(uint.MaxValue, "frame of 4294967295 bytes")]
    public async Task ALengthOutsideTheLimitIsRefusedBeforeAnyBodyIsRead(uint length, string expected)
    {
        var header = new byte[4];
        BinaryPrimitives.WriteUInt32BigEndian(header, length);
        using var s = new MemoryStream(header);
        var e = await Assert.ThrowsAsync<ProtocolException>(() => Read(s));
        Assert.Contains(expected, e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public async Task ATruncatedFrameSaysHowMuchCame()
    {
        var frame = Framing.Frame(new byte[100]);
        using var s = new MemoryStream(frame[..50]);
        var e = await Assert.ThrowsAsync<ProtocolException>(() => Read(s));
        Assert.Contains("truncated frame of 100 bytes: the connection closed after 46 of 100 bytes", e.Message, StringComparison.Ordinal);
        using var h = new MemoryStream(frame[..2]);
        Assert.Contains("truncated frame header", (await Assert.ThrowsAsync<ProtocolException>(() => Read(h))).Message, StringComparison.Ordinal);
    }

    [Fact]
    public async Task AFrameNotWholeByItsDeadlineIsASlowFrame()
    {
        // A pipe that gives the first two bytes and then nothing: the drip stops mid-frame.
        using var s = new DripStream(Framing.Frame(new byte[10])[..2]);
        var e = await Assert.ThrowsAsync<ProtocolException>(() => Read(s, TimeSpan.FromMilliseconds(50)));
        Assert.Contains("slow frame", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public async Task NoFrameWithinTheIdleTimeIsASilentPeer()
    {
        using var s = new DripStream([]);
        var e = await Assert.ThrowsAsync<ProtocolException>(() => Framing.ReadAsync(s, TimeSpan.FromMilliseconds(50), Long, CancellationToken.None));
        Assert.Contains("silent peer", e.Message, StringComparison.Ordinal);
    }

    // Gives its bytes one at a time, then waits (until cancelled) as a silent socket does.
    private sealed class DripStream(byte[] bytes) : Stream
    {
        private int _at;
        public override bool CanRead => true;
        public override bool CanSeek => false;
        public override bool CanWrite => false;
        public override long Length => throw new NotSupportedException();
        public override long Position { get => throw new NotSupportedException(); set => throw new NotSupportedException(); }
        public override void Flush() { }
        public override int Read(byte[] buffer, int offset, int count) => throw new NotSupportedException();
        public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();
        public override void SetLength(long value) => throw new NotSupportedException();
        public override void Write(byte[] buffer, int offset, int count) => throw new NotSupportedException();

        public override async ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default)
        {
            if (_at < bytes.Length)
            {
                buffer.Span[0] = bytes[_at++];
                return 1;
            }
            await Task.Delay(Timeout.Infinite, cancellationToken);
            return 0;
        }
    }
}
