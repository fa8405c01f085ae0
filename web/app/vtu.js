// Reads the VTK XML UnstructuredGrid that fosls-serve writes (solution.vtu): points,
// triangles (2D) or tetrahedra (3D), point data (u, ...) and cell data (sigma, von_mises, functional). Arrays may be
// ASCII or inline binary (format="binary": base64 of a UInt32 or UInt64 byte count and the
// little-endian values, as one stream). Plain string scanning rather than DOMParser, so the
// same code runs in the browser and under node.

const dataArrayPattern = /<DataArray\b([^>]*?)(\/>|>([\s\S]*?)<\/DataArray>)/g;
const attributePattern = /([A-Za-z_:][\w:.-]*)\s*=\s*"([^"]*)"/g;

function attributes(text) {
  const out = {};
  for (const m of text.matchAll(attributePattern)) out[m[1]] = m[2];
  return out;
}

function section(xml, tag) {
  const open = new RegExp(`<${tag}\\b[^>]*>`).exec(xml);
  if (!open) return '';
  const close = xml.indexOf(`</${tag}>`, open.index);
  return close < 0 ? '' : xml.slice(open.index + open[0].length, close);
}

const binaryTypes = {
  Float64: [Float64Array, 8], Float32: [Float32Array, 4], Int32: [Int32Array, 4], UInt32: [Uint32Array, 4],
  Int64: [BigInt64Array, 8], UInt64: [BigUint64Array, 8], UInt8: [Uint8Array, 1], Int8: [Int8Array, 1],
};

function base64Bytes(text) {
  const binary = atob(text.replace(/\s+/g, ''));
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

/** The values of an inline binary array (little-endian, as fosls-contact writes). */
function binaryValues(text, type, headerType, name) {
  const kind = binaryTypes[type];
  if (!kind) throw new Error(`DataArray "${name}": unsupported binary type ${type}`);
  const bytes = base64Bytes(text);
  const headerSize = headerType === 'UInt64' ? 8 : 4;
  if (bytes.length < headerSize) throw new Error(`DataArray "${name}": binary data without its header`);
  const view = new DataView(bytes.buffer);
  const size = headerSize === 8 ? Number(view.getBigUint64(0, true)) : view.getUint32(0, true);
  if (size > bytes.length - headerSize || size % kind[1] !== 0) {
    throw new Error(`DataArray "${name}": the header announces ${size} bytes, ${bytes.length - headerSize} follow`);
  }
  const values = new kind[0](bytes.buffer.slice(headerSize, headerSize + size));
  return kind[0] === BigInt64Array || kind[0] === BigUint64Array ? Float64Array.from(values, Number) : Float64Array.from(values);
}

function arrayList(xml, headerType) {
  const out = [];
  for (const m of xml.matchAll(dataArrayPattern)) {
    const attrs = attributes(m[1]);
    const format = attrs.format ?? 'ascii';
    const name = attrs.Name ?? '';
    const text = (m[3] ?? '').trim();
    let values;
    if (format === 'binary') {
      values = binaryValues(text, attrs.type, headerType, name);
    } else if (format === 'ascii') {
      values = text === '' ? new Float64Array(0) : Float64Array.from(text.split(/\s+/), Number);
    } else {
      throw new Error(`DataArray "${name || '?'}" is neither ASCII nor inline binary (format="${format}")`);
    }
    out.push({ name, components: Number(attrs.NumberOfComponents ?? 1), values });
  }
  return out;
}

/** Cell shapes the reader knows: VTK type → nodes per cell and the name used in messages. */
const CELL_SHAPES = { 5: { nodes: 3, name: 'triangle' }, 10: { nodes: 4, name: 'tetrahedron' } };

/**
 * The cells as one flat Uint32Array of `nodes` vertices each, all of VTK type `type`. A file
 * of one shape is required: a mixed file (or, without a types array, an offset step other than
 * the shape's) is refused with the cell that breaks it.
 */
function uniformCells(cells, nCells, nPoints, type) {
  const { connectivity, offsets, types } = cells;
  const { nodes, name } = CELL_SHAPES[type];
  const out = new Uint32Array(nodes * nCells);
  let previous = 0;
  for (let c = 0; c < nCells; c++) {
    if (offsets[c] - previous !== nodes || (types && types[c] !== type)) {
      throw new Error(type === 5 ? `cell ${c} is not a triangle`
        : `cell ${c} is not a ${name} as cell 0 is (mixed cell shapes are not read)`);
    }
    for (let k = 0; k < nodes; k++) {
      const v = connectivity[previous + k];
      if (!(v >= 0 && v < nPoints)) throw new Error(`cell ${c} names point ${v}, beyond ${nPoints}`);
      out[nodes * c + k] = v;
    }
    previous = offsets[c];
  }
  return out;
}

/** The point coordinates, the first `dimension` components of each point. */
function pointCoordinates(pointArray, nPoints, dimension) {
  const out = new Float64Array(dimension * nPoints);
  for (let v = 0; v < nPoints; v++) {
    for (let d = 0; d < dimension; d++) out[dimension * v + d] = pointArray.values[v * pointArray.components + d] ?? 0;
  }
  return out;
}

/**
 * Parses the VTU text. A file of triangles (2D) returns {points: Float64Array (x,y pairs),
 * triangles: Uint32Array (3 per cell), pointData: {name: {components, values}}, cellData:
 * {...}}. A file of tetrahedra (3D, VTK type 10) returns {dimension: 3, points3: Float64Array
 * (x,y,z triples), tetrahedra: Uint32Array (4 per cell), pointData, cellData}. Throws an Error
 * saying what is missing or inconsistent.
 */
export function parseVtu(xml) {
  const file = /<VTKFile\b([^>]*)>/.exec(xml);
  if (file && / compressor=/.test(file[1])) throw new Error('compressed VTU data are not supported');
  const headerType = attributes(file?.[1] ?? '').header_type ?? 'UInt32';
  const arrays = (part) => arrayList(part, headerType);
  const piece = /<Piece\b([^>]*)>/.exec(xml);
  if (!piece) throw new Error('not a VTK UnstructuredGrid file (no <Piece>)');
  const pieceAttrs = attributes(piece[1]);
  const nPoints = Number(pieceAttrs.NumberOfPoints);
  const nCells = Number(pieceAttrs.NumberOfCells);

  const [pointArray] = arrays(section(xml, 'Points'));
  if (!pointArray || pointArray.values.length !== nPoints * pointArray.components) {
    throw new Error(`Points: expected ${nPoints} points`);
  }

  const cells = Object.fromEntries(arrays(section(xml, 'Cells')).map((a) => [a.name, a.values]));
  if (!cells.connectivity || !cells.offsets || cells.offsets.length !== nCells) {
    throw new Error(`Cells: expected connectivity and ${nCells} offsets`);
  }
  // The shape is the first cell's (by its type, or by its node count without a types array);
  // anything but triangles and tetrahedra is refused by name.
  const firstType = cells.types ? cells.types[0] : cells.offsets[0] === 4 ? 10 : 5;
  if (nCells > 0 && !CELL_SHAPES[firstType]) {
    throw new Error(`cell 0 has VTK type ${firstType}: only triangles (5) and tetrahedra (10) are read`);
  }
  const solid = nCells > 0 && firstType === 10;
  if (solid && pointArray.components < 3) throw new Error('Points: tetrahedra need 3 coordinates per point');

  const collect = (xmlPart, count, where) => {
    const out = {};
    for (const a of arrays(xmlPart)) {
      if (a.values.length !== count * a.components) {
        throw new Error(`${where} "${a.name}": expected ${count} × ${a.components} values`);
      }
      out[a.name] = { components: a.components, values: a.values };
    }
    return out;
  };
  const data = () => ({
    pointData: collect(section(xml, 'PointData'), nPoints, 'PointData'),
    cellData: collect(section(xml, 'CellData'), nCells, 'CellData'),
  });
  if (solid) {
    const tetrahedra = uniformCells(cells, nCells, nPoints, 10);
    return { dimension: 3, points3: pointCoordinates(pointArray, nPoints, 3), tetrahedra, ...data() };
  }
  const triangles = uniformCells(cells, nCells, nPoints, 5);
  return { points: pointCoordinates(pointArray, nPoints, 2), triangles, ...data() };
}
