using Billiards.App.Native;

namespace Billiards.App.Audio;

/// <summary>
/// OpenAL Soft's side of <see cref="IAudioStream"/>: one streaming source and a queue of small
/// buffers, 48 kHz 16-bit stereo. It starts with <see cref="Buffers"/> buffers of 5 ms; OpenAL
/// Soft mixes in periods of its own (1024 frames by default, <c>period_size</c> in alsoft.conf;
/// older versions ignore ALC_REFRESH), and when a period drains the queue, the source runs dry:
/// each such underrun adds a buffer, up to <see cref="MaxBuffers"/>, so the queue settles at the
/// shortest length the device allows.
/// </summary>
internal sealed class OpenAlStream : IAudioStream
{
    /// <summary>Sample rate (Hz).</summary>
    public const int Rate = 48000;

    /// <summary>Buffers in the queue at start.</summary>
    public const int Buffers = 3;

    /// <summary>Most buffers the queue grows to (50 ms).</summary>
    public const int MaxBuffers = 10;

    /// <summary>Frames per buffer: 5 ms.</summary>
    public const int Frames = Rate / 200;

    private readonly OpenAl.Api _al;
    private readonly nint _device, _context;
    private readonly uint _source;
    private readonly List<uint> _buffers = [];
    private readonly Stack<uint> _free = new();
    private bool _started;

    private OpenAlStream(OpenAl.Api al, nint device, nint context)
    {
        _al = al;
        _device = device;
        _context = context;
        _source = al.GenSource();
        for (int i = 0; i < Buffers; i++)
        {
            AddBuffer();
        }
        DeviceName = al.DeviceName(device);
    }

    /// <summary>The opened device's name.</summary>
    public string DeviceName { get; }

    /// <summary>Buffers in use now.</summary>
    public int BufferCount => _buffers.Count;

    /// <summary>Times the source ran dry.</summary>
    public int Underruns { get; private set; }

    /// <inheritdoc />
    public int SampleRate => Rate;

    /// <inheritdoc />
    public int FramesPerBuffer => Frames;

    /// <summary>
    /// Opens a device and a context; throws <see cref="DllNotFoundException"/> without the library
    /// and <see cref="InvalidOperationException"/> naming the step that failed.
    /// </summary>
    /// <param name="deviceName">The device (null: the default one).</param>
    /// <param name="libraries">Library names to try.</param>
    public static OpenAlStream Open(string? deviceName, string[] libraries)
    {
        var al = OpenAl.Load(libraries);
        nint device = al.OpenDevice(deviceName);
        if (device == 0)
        {
            throw new InvalidOperationException(deviceName is null ? "no audio device" : $"no audio device \"{deviceName}\"");
        }
        ReadOnlySpan<int> attributes = [OpenAl.AlcFrequency, Rate, OpenAl.AlcRefresh, Rate / Frames, 0];
        nint context = al.CreateContext(device, attributes);
        if (context == 0 || !al.MakeContextCurrent(context))
        {
            if (context != 0)
            {
                al.DestroyContext(context);
            }
            al.CloseDevice(device);
            throw new InvalidOperationException("the audio device opened, but no OpenAL context could be made on it");
        }
        return new OpenAlStream(al, device, context);
    }

    /// <inheritdoc />
    public int FreeBuffers()
    {
        int processed = _al.GetSource(_source, OpenAl.BuffersProcessed);
        for (int i = 0; i < processed; i++)
        {
            _free.Push(_al.Unqueue(_source));
        }
        if (_started && _al.GetSource(_source, OpenAl.BuffersQueued) == 0)
        {
            Underruns++;
            if (_buffers.Count < MaxBuffers)
            {
                AddBuffer();
            }
        }
        return _free.Count;
    }

    private void AddBuffer()
    {
        Span<uint> one = stackalloc uint[1];
        _al.GenBuffers(one);
        _buffers.Add(one[0]);
        _free.Push(one[0]);
    }

    /// <inheritdoc />
    public int PendingFrames()
    {
        int queued = _al.GetSource(_source, OpenAl.BuffersQueued);
        if (queued == 0)
        {
            return 0;
        }
        int played = _al.GetSource(_source, OpenAl.BuffersProcessed);
        int offset = _al.GetSource(_source, OpenAl.SampleOffset);
        return Math.Max(0, ((queued - played) * Frames) - offset);
    }

    /// <inheritdoc />
    public void Submit(ReadOnlySpan<short> interleaved)
    {
        uint buffer = _free.Pop();
        _al.BufferData(buffer, interleaved, Rate);
        _al.Queue(_source, buffer);
        // Starting, or restarting after an underrun (the source stops when its queue runs dry).
        if (_al.GetSource(_source, OpenAl.SourceState) != OpenAl.Playing)
        {
            _al.Play(_source);
        }
        _started = true;
    }

    /// <inheritdoc />
    public void Dispose()
    {
        _al.Stop(_source);
        int queued = _al.GetSource(_source, OpenAl.BuffersQueued);
        for (int i = 0; i < queued; i++)
        {
            _al.Unqueue(_source);
        }
        _al.DeleteSource(_source);
        _al.DeleteBuffers(_buffers.ToArray());
        _al.MakeContextCurrent(0);
        _al.DestroyContext(_context);
        _al.CloseDevice(_device);
    }
}
