// A QR code as one SVG path: each dark module a unit square, so a tablet's
// camera reads a participant's link from the screen instead of it being typed.
import QRCode from "qrcode";

export function qrPath(text: string): { size: number; path: string } {
  const { modules } = QRCode.create(text, { errorCorrectionLevel: "M" });
  const squares: string[] = [];
  for (let row = 0; row < modules.size; row++)
    for (let col = 0; col < modules.size; col++)
      if (modules.data[row * modules.size + col]) squares.push(`M${col} ${row}h1v1h-1z`);
  return { size: modules.size, path: squares.join("") };
}
