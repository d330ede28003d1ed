// The demo picture on a 320 x 240 panel, whole and centred (TS_FIT_INSIDE), in bands of 16 rows of
// RGB565 (high byte first, as SPI panels such as the ST7789 and ILI9341 take it). send_band is where
// a sketch hands each band to its display driver; here it folds the pixels into a checksum, printed
// with the time the frame took.
//
// The library is C++17: build_opt.h passes -std=gnu++17 on Arduino-ESP32, whose default is older
// (README.md, "Firmware ecosystems"). photo.c and photo.h come from tripack (the release folder
// holds them for the demo picture):
//   tripack photo.tri -o photo.c --symbol photo --width 320 --height 240 --tile-width 0 --tile-height 16
#include <tristream.h>

#include "photo.h"

static const int panel_width = 320;
static const int panel_height = 240;

static uint8_t band_buffer[PHOTO_TILE_BUFFER_MAX_BYTES];
static uint8_t workspace[PHOTO_WORKSPACE_MAX_BYTES];

struct Frame {
  uint32_t checksum;
  long pixels;
};

static void send_band(void* context, const ts_tile* band) {
  Frame* frame = static_cast<Frame*>(context);
  const int width = band->rect.x1 - band->rect.x0;
  const int height = band->rect.y1 - band->rect.y0;
  for (int y = 0; y < height; ++y) {
    const uint8_t* row = band->pixels + static_cast<long>(y) * band->stride;
    for (int x = 0; x < 2 * width; ++x) frame->checksum = frame->checksum * 31u + row[x];
  }
  frame->pixels += static_cast<long>(width) * height;
}

void setup() {
  Serial.begin(115200);
  ts_blob blob;
  ts_status s = ts_open(photo.bytes, photo.size, &blob, nullptr);
  if (s != TS_OK) {
    Serial.print("ts_open: ");
    Serial.println(ts_status_text(s));
    return;
  }
  ts_params params = TS_PARAMS_INIT;
  params.output_width = panel_width;
  params.output_height = panel_height;
  params.fit = TS_FIT_INSIDE;
  params.tile_height = 16;  // tile width 0: bands as wide as the panel
  params.format = TS_RGB565_BE;
  Frame frame = {0, 0};
  const unsigned long start = millis();
  s = ts_render(&blob, &params, band_buffer, sizeof band_buffer, workspace, sizeof workspace, send_band, &frame);
  const unsigned long elapsed = millis() - start;
  if (s != TS_OK) {
    Serial.print("ts_render: ");
    Serial.println(ts_status_text(s));
    return;
  }
  Serial.print("tristream " TRISTREAM_VERSION ": ");
  Serial.print(frame.pixels);
  Serial.print(" pixels in ");
  Serial.print(elapsed);
  Serial.print(" ms, checksum ");
  Serial.println(frame.checksum, HEX);
}

void loop() {}
