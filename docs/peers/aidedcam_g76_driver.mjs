// Runs aidedcam/aidedcam-page js/gcode/cycles/g76.js (commit a6817cc0081f1c8c700916ca9a2c8f408cd3823f,
// saved unchanged as the file named in argv[2]) on the parameters that js/gcode/cycles/index.js
// (same commit, HANDLERS[76]) derives from the two FANUC blocks
//   G76 P010060 Q50 R0;  G76 X18.16 Z-20.0 R<i> P920 Q300 F1.5;   from A = X22 Z2 (diameter).
// index.js readFirst: finishPasses = floor(10060/10000) = 1, chamfer = floor(10060/100) % 100 = 0,
// minDepth = microOf(Q50) = 0.05, finishAllow = lengthOf(R0) = 0; run: height = microOf(P920) = 0.92,
// firstDepth = microOf(Q300) = 0.3, taper = lengthOf(R) (mm, radius), end = targetOf(X18.16 Z-20)
// = radius 9.08 (machine.js targetOf halves X when settings.xDiameter).
const mod = await import(process.argv[2] || '/tmp/aidedcam/g76.mjs');
for (const [title, taper] of [['straight (R0)', 0], ['taper (R-0.5)', -0.5]]) {
  const depths = mod.g76Depths({ height: 0.92, firstDepth: 0.3, minDepth: 0.05, finishAllow: 0, finishPasses: 1 });
  const moves = mod.g76Moves({ start: { x: 11, z: 2 }, end: { x: 9.08, z: -20 }, depths, height: 0.92, chamferLen: 0, taper });
  console.log(`== ${title}: depths ${depths.map(d => d.toFixed(4)).join(' ')}`);
  for (const m of moves) {
    if (m.kind !== 'thread') continue;
    const f = p => `X${(2 * p.x).toFixed(4)} Z${p.z.toFixed(4)}`;
    console.log(`   pass ${m.passIndex + 1}: thread ${f(m.from)} -> ${f(m.to)}`);
  }
  const r = moves.filter(m => m.passIndex === 0).map(m => `${m.kind} ${(2 * m.to.x).toFixed(3)},${m.to.z.toFixed(3)}`);
  console.log(`   moves of pass 1 (dia, Z): ${r.join(' | ')}`);
}
