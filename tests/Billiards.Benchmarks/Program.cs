using BenchmarkDotNet.Running;

// A failed or invalid benchmark fails the run, so CI's dry smoke job notices a broken benchmark.
var summaries = BenchmarkSwitcher.FromAssembly(typeof(Billiards.Benchmarks.StepBenchmarks).Assembly).Run(args);
return summaries.Any(s => s.HasCriticalValidationErrors || s.Reports.Any(r => !r.Success)) ? 1 : 0;
