import QRCode from "qrcode";
import { describe, expect, it } from "vitest";
import { qrPath } from "./qr-code";

describe("a link's QR code as a path", () => {
  it.each([
    ["a short link", "http://127.0.0.1:3000/q/abc"],
    ["a participant link of 50 characters and more", `http://lab.example.org/q/${"x".repeat(43)}`],
  ])("%s: one square per dark module, where the module is", (_, link) => {
    const { size, path } = qrPath(link);
    const { modules } = QRCode.create(link, { errorCorrectionLevel: "M" });
    expect(size).toBe(modules.size);
    const drawn = new Set([...path.matchAll(/M(\d+) (\d+)/g)].map(([, x, y]) => Number(y) * size + Number(x)));
    const dark = new Set([...modules.data.keys()].filter((i) => modules.data[i]));
    expect(drawn).toEqual(dark);
  });
});
