using System.IO.Compression;
using System.Text;

namespace Billiards.App.Net;

/// <summary>
/// How the host's whole game crosses the wire in messages of at most 64 KB: the game record's
/// UTF-8 is compressed (Brotli), written as base64, and cut into parts of at most
/// <see cref="PartChars"/> characters, each its own <see cref="Resync"/> message; the joiner
/// joins the parts in order and unpacks them, refusing more than <see cref="MaxParts"/> parts or
/// a record that unpacks to more than <see cref="MaxRecordBytes"/>.
/// </summary>
public static class ResyncPacking
{
    /// <summary>Most characters of one part (its message stays well under 64 KB).</summary>
    public const int PartChars = 48_000;

    /// <summary>Most parts of one game (about 2.3 MB compressed).</summary>
    public const int MaxParts = 64;

    /// <summary>Largest record a resync unpacks to (bytes): more is refused, not read on.</summary>
    public const int MaxRecordBytes = 32 << 20;

    /// <summary>The parts of <paramref name="record"/>, each at most <paramref name="partChars"/> characters.</summary>
    /// <exception cref="ArgumentException">When the record needs more than <see cref="MaxParts"/> parts.</exception>
    public static IReadOnlyList<string> Pack(string record, int partChars = PartChars)
    {
        ArgumentNullException.ThrowIfNull(record);
        ArgumentOutOfRangeException.ThrowIfLessThan(partChars, 4);
        using var packed = new MemoryStream();
        using (var brotli = new BrotliStream(packed, CompressionLevel.Optimal, leaveOpen: true))
        {
            brotli.Write(Encoding.UTF8.GetBytes(record));
        }
        string text = Convert.ToBase64String(packed.GetBuffer(), 0, (int)packed.Length);
        var parts = text.Chunk(partChars).Select(c => new string(c)).ToList();
        if (parts.Count == 0)
        {
            parts.Add("");
        }
        return parts.Count <= MaxParts ? parts : throw new ArgumentException($"the game packs into {parts.Count} parts, more than {MaxParts}", nameof(record));
    }

    /// <summary>The record the joined parts hold.</summary>
    /// <exception cref="ProtocolException">Not base64, not Brotli, more than <see cref="MaxRecordBytes"/>, or not UTF-8.</exception>
    public static string Unpack(string joined)
    {
        ArgumentNullException.ThrowIfNull(joined);
        byte[] packed;
        try
        {
            packed = Convert.FromBase64String(joined);
        }
        catch (FormatException)
        {
            throw new ProtocolException("resync: the record's parts are not base64");
        }
        using var record = new MemoryStream();
        try
        {
            using var brotli = new BrotliStream(new MemoryStream(packed), CompressionMode.Decompress);
            var buffer = new byte[81920];
            int n;
            while ((n = brotli.Read(buffer)) > 0)
            {
                if (record.Length + n > MaxRecordBytes)
                {
                    throw new ProtocolException($"resync: the record unpacks to more than {MaxRecordBytes} bytes");
                }
                record.Write(buffer, 0, n);
            }
        }
        catch (Exception e) when (e is InvalidDataException or InvalidOperationException)
        {
            // Brotli's decoder says "invalid data" one way or the other.
            throw new ProtocolException("resync: the record's parts are not a compressed record");
        }
        try
        {
            return new UTF8Encoding(false, throwOnInvalidBytes: true).GetString(record.GetBuffer(), 0, (int)record.Length);
        }
        catch (DecoderFallbackException)
        {
            throw new ProtocolException("resync: the record is not UTF-8");
        }
    }
}
