using System.Runtime.InteropServices;

namespace Billiards.App.Native;

/// <summary>
/// OpenAL 1.1 (OpenAL Soft): the few functions streaming needs, bound at first use like
/// <see cref="Glfw"/>. On Windows, OpenAL Soft's <c>soft_oal.dll</c> renamed <c>OpenAL32.dll</c>
/// (or as it is) goes next to the executable.
/// </summary>
internal static unsafe class OpenAl
{
    public const int FormatStereo16 = 0x1103;
    public const int SourceState = 0x1010, Playing = 0x1012, BuffersQueued = 0x1015, BuffersProcessed = 0x1016, SampleOffset = 0x1025;
    public const int Gain = 0x100A;
    public const int AlcFrequency = 0x1007, AlcRefresh = 0x1008, AlcDeviceSpecifier = 0x1005, AlcAllDevicesSpecifier = 0x1013;

    /// <summary>The library names tried, in order, on this platform.</summary>
    public static string[] DefaultLibraries { get; } =
        OperatingSystem.IsWindows() ? ["OpenAL32.dll", "soft_oal.dll"] :
        OperatingSystem.IsMacOS() ? ["libopenal.1.dylib", "libopenal.dylib", "/System/Library/Frameworks/OpenAL.framework/OpenAL"] :
        ["libopenal.so.1", "libopenal.so"];

    /// <summary>Loads the library from <paramref name="candidates"/>; throws <see cref="DllNotFoundException"/> naming them.</summary>
    public static Api Load(string[] candidates)
    {
        QuietNativeLogs();
        return new(NativeLoader.Load("OpenAL Soft", candidates));
    }

    /// <summary>
    /// Without an audio device the game says so in one line of its own; OpenAL Soft and ALSA would
    /// each add lines of their own on stderr. OpenAL Soft reads ALSOFT_LOGLEVEL from the process
    /// environment when it loads (set natively: .NET keeps its own copy of the environment), and
    /// ALSA takes an error handler. A user's own ALSOFT_LOGLEVEL is kept.
    /// </summary>
    private static void QuietNativeLogs()
    {
        if (!OperatingSystem.IsLinux())
        {
            return;
        }
        if (NativeLibrary.TryLoad("libc.so.6", out nint libc) && NativeLibrary.TryGetExport(libc, "setenv", out nint setenv))
        {
            byte* name = (byte*)Marshal.StringToCoTaskMemUTF8("ALSOFT_LOGLEVEL");
            byte* value = (byte*)Marshal.StringToCoTaskMemUTF8("0");
            ((delegate* unmanaged<byte*, byte*, int, int>)setenv)(name, value, 0);
            Marshal.FreeCoTaskMem((nint)name);
            Marshal.FreeCoTaskMem((nint)value);
        }
        if (NativeLibrary.TryLoad("libasound.so.2", out nint alsa) && NativeLibrary.TryGetExport(alsa, "snd_lib_error_set_handler", out nint setHandler))
        {
            ((delegate* unmanaged<delegate* unmanaged<nint, int, nint, int, nint, void>, int>)setHandler)(&IgnoreAlsaError);
        }
    }

    // ALSA's handler is variadic; the arguments after the format are never read here.
    [UnmanagedCallersOnly]
    private static void IgnoreAlsaError(nint file, int line, nint function, int error, nint format)
    {
    }

    /// <summary>The functions of one loaded OpenAL library.</summary>
    internal sealed class Api(nint library)
    {
        private readonly delegate* unmanaged<byte*, nint> _openDevice = (delegate* unmanaged<byte*, nint>)NativeLoader.Export(library, "alcOpenDevice");
        private readonly delegate* unmanaged<nint, byte> _closeDevice = (delegate* unmanaged<nint, byte>)NativeLoader.Export(library, "alcCloseDevice");
        private readonly delegate* unmanaged<nint, int*, nint> _createContext = (delegate* unmanaged<nint, int*, nint>)NativeLoader.Export(library, "alcCreateContext");
        private readonly delegate* unmanaged<nint, byte> _makeContextCurrent = (delegate* unmanaged<nint, byte>)NativeLoader.Export(library, "alcMakeContextCurrent");
        private readonly delegate* unmanaged<nint, void> _destroyContext = (delegate* unmanaged<nint, void>)NativeLoader.Export(library, "alcDestroyContext");
        private readonly delegate* unmanaged<nint, int, byte*> _alcGetString = (delegate* unmanaged<nint, int, byte*>)NativeLoader.Export(library, "alcGetString");
        private readonly delegate* unmanaged<int, uint*, void> _genSources = (delegate* unmanaged<int, uint*, void>)NativeLoader.Export(library, "alGenSources");
        private readonly delegate* unmanaged<int, uint*, void> _deleteSources = (delegate* unmanaged<int, uint*, void>)NativeLoader.Export(library, "alDeleteSources");
        private readonly delegate* unmanaged<int, uint*, void> _genBuffers = (delegate* unmanaged<int, uint*, void>)NativeLoader.Export(library, "alGenBuffers");
        private readonly delegate* unmanaged<int, uint*, void> _deleteBuffers = (delegate* unmanaged<int, uint*, void>)NativeLoader.Export(library, "alDeleteBuffers");
        private readonly delegate* unmanaged<uint, int, void*, int, int, void> _bufferData = (delegate* unmanaged<uint, int, void*, int, int, void>)NativeLoader.Export(library, "alBufferData");
        private readonly delegate* unmanaged<uint, int, uint*, void> _queueBuffers = (delegate* unmanaged<uint, int, uint*, void>)NativeLoader.Export(library, "alSourceQueueBuffers");
        private readonly delegate* unmanaged<uint, int, uint*, void> _unqueueBuffers = (delegate* unmanaged<uint, int, uint*, void>)NativeLoader.Export(library, "alSourceUnqueueBuffers");
        private readonly delegate* unmanaged<uint, int, int*, void> _getSourcei = (delegate* unmanaged<uint, int, int*, void>)NativeLoader.Export(library, "alGetSourcei");
        private readonly delegate* unmanaged<uint, int, float, void> _sourcef = (delegate* unmanaged<uint, int, float, void>)NativeLoader.Export(library, "alSourcef");
        private readonly delegate* unmanaged<uint, void> _sourcePlay = (delegate* unmanaged<uint, void>)NativeLoader.Export(library, "alSourcePlay");
        private readonly delegate* unmanaged<uint, void> _sourceStop = (delegate* unmanaged<uint, void>)NativeLoader.Export(library, "alSourceStop");
        private readonly delegate* unmanaged<int> _getError = (delegate* unmanaged<int>)NativeLoader.Export(library, "alGetError");

        /// <summary>Opens a device by name (null: the default device); 0 when it cannot.</summary>
        public nint OpenDevice(string? name)
        {
            if (name is null)
            {
                return _openDevice(null);
            }
            byte* n = (byte*)Marshal.StringToCoTaskMemUTF8(name);
            try
            {
                return _openDevice(n);
            }
            finally
            {
                Marshal.FreeCoTaskMem((nint)n);
            }
        }

        public void CloseDevice(nint device) => _closeDevice(device);

        public nint CreateContext(nint device, ReadOnlySpan<int> attributes)
        {
            fixed (int* a = attributes)
            {
                return _createContext(device, a);
            }
        }

        public bool MakeContextCurrent(nint context) => _makeContextCurrent(context) != 0;

        public void DestroyContext(nint context) => _destroyContext(context);

        public string DeviceName(nint device) => Marshal.PtrToStringUTF8((nint)_alcGetString(device, AlcDeviceSpecifier)) ?? "";

        public uint GenSource()
        {
            uint s;
            _genSources(1, &s);
            return s;
        }

        public void DeleteSource(uint source) => _deleteSources(1, &source);

        public void GenBuffers(Span<uint> buffers)
        {
            fixed (uint* b = buffers)
            {
                _genBuffers(buffers.Length, b);
            }
        }

        public void DeleteBuffers(ReadOnlySpan<uint> buffers)
        {
            fixed (uint* b = buffers)
            {
                _deleteBuffers(buffers.Length, b);
            }
        }

        public void BufferData(uint buffer, ReadOnlySpan<short> interleaved, int sampleRate)
        {
            fixed (short* d = interleaved)
            {
                _bufferData(buffer, FormatStereo16, d, interleaved.Length * sizeof(short), sampleRate);
            }
        }

        public void Queue(uint source, uint buffer) => _queueBuffers(source, 1, &buffer);

        public uint Unqueue(uint source)
        {
            uint b;
            _unqueueBuffers(source, 1, &b);
            return b;
        }

        public int GetSource(uint source, int parameter)
        {
            int value;
            _getSourcei(source, parameter, &value);
            return value;
        }

        public void SetSource(uint source, int parameter, float value) => _sourcef(source, parameter, value);

        public void Play(uint source) => _sourcePlay(source);

        public void Stop(uint source) => _sourceStop(source);

        public int GetError() => _getError();
    }
}
