function value = beft_json_decode(text, hex)
%BEFT_JSON_DECODE  A message from the bridge's JSON, every double exact (NaN for null).
%   value = beft_json_decode(text)
%   value = beft_json_decode(numbered_text, hex)   (what beft.BridgeSocket gives)
%   As jsondecode: objects are structs, arrays of objects struct arrays,
%   arrays of numbers column vectors, a member name that is no MATLAB name
%   is renamed. Numbers are read by Java's Double.parseDouble
%   (beft.JsonNumbers): jsondecode gets the text with every number replaced
%   by its position and parses only small integers, which it gets right
%   (Octave's jsondecode is off by one ULP on about one double in five). A
%   null, on the wire a NaN or infinite double, is NaN.
  if nargin < 2
    numbers = javaObject('beft.JsonNumbers', text);
    text = char(numbers.text());
    hex = char(numbers.hex());
  end
  value = jsondecode(text);
  if ~isempty(hex)
    value = exact_numbers(value, hex2num(reshape(hex, 16, [])'));
  end
end

% Every number in v is a position in exact; logicals and text stay as they are.
function v = exact_numbers(v, exact)
  if isnumeric(v)
    v(:) = exact(v(:));
  elseif isstruct(v) && ~isempty(v)
    names = fieldnames(v);
    if ~isempty(names)
      cells = exact_cells(struct2cell(v), exact);  % members x elements, at once
      v = reshape(cell2struct(reshape(cells, numel(names), []), names, 1), size(v));
    end
  elseif iscell(v)
    v = exact_cells(v, exact);
  end
end

function c = exact_cells(c, exact)
  numbers = cellfun('isclass', c, 'double');
  scalars = numbers & cellfun('prodofsize', c) == 1;
  if any(scalars(:))
    c(scalars) = num2cell(exact([c{scalars}]));
  end
  arrays = find(numbers & ~scalars);
  for k = reshape(arrays, 1, [])
    c{k}(:) = exact(c{k}(:));
  end
  nested = find(cellfun('isclass', c, 'struct') | cellfun('isclass', c, 'cell'));
  for k = reshape(nested, 1, [])
    c{k} = exact_numbers(c{k}, exact);
  end
end
