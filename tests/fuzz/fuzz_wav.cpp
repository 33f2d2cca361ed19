// Fuzz target: WAV sound effects. Seeds: synthetic_wav_seeds() plus the game's *.wav files.
#include "fuzz_target.h"
#include "sound/sound_sample.h"
#include "sound/wav.h"
#include "support/synth_wav.h"

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    nq::fuzz::handle_write_seeds(*argc, *argv, nq::test::synthetic_wav_seeds());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    auto wav = nq::parse_wav({data, size}, "fuzz.wav");
    if (!wav) {
        volatile size_t sink = wav.error().to_string().size();
        (void)sink;
        return 0;
    }
    // Resample as precaching does (to a rate that makes the buffer small), then read it all.
    nq::SoundSample sample = nq::resample(*wav, 11025);
    int64_t sum = sample.loop_start;
    for (int16_t s : sample.frames) sum += s;
    if (sample.loop_start >= 0) sum += sample.frames.at(size_t(sample.loop_start));
    volatile int64_t sink = sum;
    (void)sink;
    return 0;
}
