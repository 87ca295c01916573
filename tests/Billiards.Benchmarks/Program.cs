using BenchmarkDotNet.Running;

BenchmarkSwitcher.FromAssembly(typeof(Billiards.Benchmarks.StepBenchmarks).Assembly).Run(args);
