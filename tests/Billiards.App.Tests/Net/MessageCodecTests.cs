using System.Text;
using Billiards.App.Net;

namespace Billiards.App.Tests.Net;

/// <summary>The wire's messages: every kind round-trips, and every malformed or out-of-range field is refused with a line naming it.</summary>
public class MessageCodecTests
{
    public static TheoryData<Message> Messages => new()
    {
        new Hello("0.1.0", "ABCDEF", null, 0),
        new Hello("0.1.0", "ABCDEF", new HostGame("{\"format\":\"x\"}", "{}", new string('a', 64), "Anna", "Ben"), 12),
        new Stroke(3, 2.5, -179.25, 0.125, -0.25, 5, true),
        new Placement(0, -0.8, 0.1),
        new CallMessage(4, 8, "top-left"),
        new CallMessage(4, null, null),
        new Choice(5, "accept"),
        new StateHash(6, new string('0', 64), new string('f', 64)),
        new Resync(7, 0, 1, "G0sAAIyU"),
        new Resync(70, 2, 3, new string('A', ResyncPacking.PartChars)),
        new Ping(42, true),
        new Bye("refused: wrong code"),
    };

    [Theory]
    [MemberData(nameof(Messages))]
    public void EveryKindRoundTrips(Message message)
    {
        var back = MessageCodec.Parse(MessageCodec.Write(message));
        Assert.Equal(message, back);
    }

    [Theory]
    [InlineData("not json", "malformed JSON")]
    [InlineData("[1,2]", "a message is a JSON object")]
    [InlineData("{\"kind\":\"ping\",\"id\":1,\"reply\":false}", "missing field \"v\"")]
    [InlineData("{\"v\":2,\"kind\":\"ping\",\"id\":1,\"reply\":false}", "protocol version 2")]
    [InlineData("{\"v\":1,\"kind\":\"exec\"}", "unknown kind \"exec\"")]
    [InlineData("{\"v\":1,\"kind\":\"ping\",\"id\":1,\"reply\":false,\"$type\":\"System.Object\"}", "unknown field \"$type\"")]
    [InlineData("{\"v\":1,\"kind\":\"ping\",\"id\":1,\"id\":2,\"reply\":false}", "field \"id\" twice")]
    [InlineData("{\"v\":1,\"kind\":\"stroke\",\"shot\":0,\"speed\":NaN,\"aim_deg\":0,\"tip_side\":0,\"tip_height\":0,\"elevation_deg\":0,\"push_out\":false}", "malformed JSON")]
    [InlineData("{\"v\":1,\"kind\":\"stroke\",\"shot\":0,\"speed\":1e999,\"aim_deg\":0,\"tip_side\":0,\"tip_height\":0,\"elevation_deg\":0,\"push_out\":false}", "\"speed\": not a finite number")]
    [InlineData("{\"v\":1,\"kind\":\"stroke\",\"shot\":0,\"speed\":\"NaN\",\"aim_deg\":0,\"tip_side\":0,\"tip_height\":0,\"elevation_deg\":0,\"push_out\":false}", "\"speed\": expected number, not string")]
    [InlineData("{\"v\":1,\"kind\":\"stroke\",\"shot\":0,\"speed\":21,\"aim_deg\":0,\"tip_side\":0,\"tip_height\":0,\"elevation_deg\":0,\"push_out\":false}", "\"speed\": 21 is out of range")]
    [InlineData("{\"v\":1,\"kind\":\"stroke\",\"shot\":0,\"speed\":2,\"aim_deg\":400,\"tip_side\":0,\"tip_height\":0,\"elevation_deg\":0,\"push_out\":false}", "\"aim_deg\": 400 is out of range")]
    [InlineData("{\"v\":1,\"kind\":\"stroke\",\"shot\":0,\"speed\":2,\"aim_deg\":0,\"tip_side\":0.8,\"tip_height\":0.8,\"elevation_deg\":0,\"push_out\":false}", "the tip offset must lie inside the ball")]
    [InlineData("{\"v\":1,\"kind\":\"stroke\",\"shot\":0,\"speed\":2,\"aim_deg\":0,\"tip_side\":0,\"tip_height\":0,\"elevation_deg\":91,\"push_out\":false}", "\"elevation_deg\": 91 is out of range")]
    [InlineData("{\"v\":1,\"kind\":\"stroke\",\"shot\":-1,\"speed\":2,\"aim_deg\":0,\"tip_side\":0,\"tip_height\":0,\"elevation_deg\":0,\"push_out\":false}", "\"shot\": -1 is out of range")]
    [InlineData("{\"v\":1,\"kind\":\"stroke\",\"shot\":0,\"speed\":2,\"aim_deg\":0,\"tip_side\":0,\"tip_height\":0,\"elevation_deg\":0}", "missing field \"push_out\"")]
    [InlineData("{\"v\":1,\"kind\":\"placement\",\"shot\":0,\"x\":99,\"y\":0}", "\"x\": 99 is out of range")]
    [InlineData("{\"v\":1,\"kind\":\"state_hash\",\"shot\":0,\"balls\":\"abc\",\"ruling\":\"abc\"}", "expected 64 lowercase hex digits")]
    [InlineData("{\"v\":1,\"kind\":\"bye\",\"reason\":\"a\\nb\"}", "a control character")]
    [InlineData("{\"v\":1,\"kind\":\"resync\",\"shot\":1,\"part\":3,\"parts\":3,\"record\":\"AAAA\"}", "resync: part 3 of 3")]
    [InlineData("{\"v\":1,\"kind\":\"resync\",\"shot\":1,\"part\":0,\"parts\":65,\"record\":\"AAAA\"}", "\"parts\": 65 is out of range")]
    [InlineData("{\"v\":1,\"kind\":\"resync\",\"shot\":1,\"part\":0,\"parts\":1}", "missing field \"record\"")]
    [InlineData("{\"v\":1,\"kind\":\"ping\",\"id\":1.5,\"reply\":false}", "\"id\": not an integer")]
    [InlineData("{\"v\":1,\"kind\":\"ping\",\"id\":1,\"reply\":{\"a\":{\"b\":{\"c\":{\"d\":{\"e\":{\"f\":{\"g\":{\"h\":1}}}}}}}}}", "malformed JSON")]
    public void ABadMessageIsRefusedWithALineNamingWhatIsWrong(string json, string expected)
    {
        var e = Assert.Throws<ProtocolException>(() => MessageCodec.Parse(Encoding.UTF8.GetBytes(json)));
        Assert.Contains(expected, e.Message, StringComparison.Ordinal);
        Assert.DoesNotContain('\n', e.Message);
    }

    [Fact]
    public void ACodeIsSixCharactersOfTheAlphabetAndNewCodesAreSeeded()
    {
        string a = MessageCodec.NewCode(new Random(38));
        Assert.True(MessageCodec.IsCode(a));
        Assert.Equal(a, MessageCodec.NewCode(new Random(38)));
        Assert.False(MessageCodec.IsCode("ABCDE"));
        Assert.False(MessageCodec.IsCode("ABCDE0"));
        Assert.False(MessageCodec.IsCode("abcdef"));
    }
}

/// <summary>The host's game packed into resync parts: it unpacks to the same text, and a hostile packing is refused with its line.</summary>
public class ResyncPackingTests
{
    [Fact]
    public void AGameLargerThanOneMessagePacksIntoPartsThatUnpackToTheSameText()
    {
        // 300 KB of record-like text with little repetition.
        var random = new Random(38);
        string record = string.Concat(Enumerable.Range(0, 10_000).Select(i => $"{{\"shot\":{i},\"x\":{random.NextDouble():R}}},"));
        Assert.True(Encoding.UTF8.GetByteCount(record) > 3 * Framing.MaxMessageBytes);
        var parts = ResyncPacking.Pack(record, partChars: 10_000);
        Assert.True(parts.Count > 1, $"{parts.Count} part(s)");
        Assert.All(parts, p => Assert.True(p.Length <= 10_000));
        Assert.All(parts, p => Assert.True(MessageCodec.Write(new Resync(1, 0, parts.Count, p)).Length <= Framing.MaxMessageBytes));
        Assert.Equal(record, ResyncPacking.Unpack(string.Concat(parts)));
    }

    [Fact]
    public void NotBase64NotCompressedAndABombAreRefused()
    {
        Assert.Contains("not base64", Assert.Throws<ProtocolException>(() => ResyncPacking.Unpack("!!!")).Message, StringComparison.Ordinal);
        Assert.Contains("not a compressed record", Assert.Throws<ProtocolException>(() => ResyncPacking.Unpack(Convert.ToBase64String(Encoding.UTF8.GetBytes("plain text, not brotli at all")))).Message, StringComparison.Ordinal);
        // 40 MB of one letter compresses to a few hundred bytes and is refused at the limit, not unpacked whole.
        var bomb = ResyncPacking.Pack(new string('a', ResyncPacking.MaxRecordBytes + (8 << 20)));
        Assert.Single(bomb);
        Assert.Contains($"more than {ResyncPacking.MaxRecordBytes} bytes", Assert.Throws<ProtocolException>(() => ResyncPacking.Unpack(bomb[0])).Message, StringComparison.Ordinal);
    }
}
