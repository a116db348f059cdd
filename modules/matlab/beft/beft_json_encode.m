function text = beft_json_encode(value, schema)
%BEFT_JSON_ENCODE  A message as JSON for the bridge, every double exact.
%   text = beft_json_encode(value)
%   text = beft_json_encode(value, schema)
%   A struct is an object, a char row a string, a logical true or false, a
%   cell array or a struct array of other than one element an array, a
%   numeric scalar a number and a vector an array. NaN and infinities are
%   null (a NaN double on the wire). A double is written with 17
%   significant digits, which read back to the same bits (-0 as -0.0), an
%   integral one as an integer.
%
%   SCHEMA, the JSON Schema of the message's type as the bridge advertises
%   it (decoded), settles what the value alone cannot: a member that is an
%   array is one even with one element or none, an integer member is
%   written as an integer (0 also for -0), a boolean one as true or false
%   (also from 0 or 1).
%
%   Values are classified and formatted a member (or an array) at a time:
%   a function call per value costs Octave tens of microseconds.
  if nargin < 2
    schema = [];
  end
  text = encode(value, schema);
end

function text = encode(value, schema)
  type = schema_type(schema);
  if strcmp(type, 'array') || (isempty(type) && is_array(value))
    text = encode_array(value, schema_items(schema));
  elseif isstruct(value)
    objects = object_texts(value, schema);
    text = objects{1};
  else
    texts = value_texts({value}, {type}, {schema}, 1);
    text = texts{1};
  end
end

function yes = is_array(value)
  yes = iscell(value) || (~ischar(value) && numel(value) ~= 1);
end

function text = encode_array(value, items)
  type = schema_type(items);
  if ischar(value)
    value = {value};  % one string where an array of strings is wanted
  end
  if isstruct(value)
    texts = object_texts(value, items);
  elseif strcmp(type, 'array') && ismatrix(value) && ~isvector(value) && ~iscell(value)
    texts = arrayfun(@(row) encode(value(row, :), items), 1:size(value, 1), 'UniformOutput', false);
  else
    if ~iscell(value)
      value = num2cell(value);
    end
    n = numel(value);
    same = ones(1, n);
    texts = value_texts(reshape(value, 1, n), {type}, {items}, same);
  end
  text = ['[' joined(texts) ']'];
end

% The objects of a struct array, each as JSON text.
function texts = object_texts(value, schema)
  names = fieldnames(value);
  n = numel(value);
  if isempty(names)
    texts = cell(1, n);
    texts(:) = {'{}'};
    return;
  end
  cells = reshape(struct2cell(reshape(value, 1, n)), numel(names), n);
  [types, schemas] = member_schemas(schema, names);
  values = value_texts(cells, types, schemas, ones(1, n));
  % One format for every object; char(1) cannot occur in values (quoted()
  % escapes it): it separates the objects.
  format = [sprintf('"%s":%%s,', names{:}) char(1)];
  format = ['{' format(1:end - 2) '}' char(1)];
  texts = regexp(sprintf(format, values{:}), char(1), 'split');
  texts = texts(1:n);
end

function text = joined(texts)
  if isempty(texts)
    text = '';
  else
    text = sprintf('%s,', texts{:});
    text = text(1:end - 1);
  end
end

function [types, schemas] = member_schemas(schema, names)
  types = cell(numel(names), 1);
  types(:) = {''};
  schemas = cell(numel(names), 1);
  if ~isstruct(schema) || ~isfield(schema, 'properties')
    return;
  end
  properties = schema.properties;
  for i = 1:numel(names)  % no function call here: this runs for every object written
    if isfield(properties, names{i})
      member = properties.(names{i});
      schemas{i} = member;
      if isfield(member, 'type')
        types{i} = member.type;
      end
    end
  end
end

% Each value as JSON; types and schemas per row of c, the same for every
% column (columns: ones(1, number of columns)).
function texts = value_texts(c, types, schemas, columns)
  types = types(:, columns);
  texts = cell(size(c));
  scalar = cellfun('prodofsize', c) == 1;
  strings = cellfun('isclass', c, 'char');
  array = strcmp(types, 'array') | (cellfun('isempty', types) & (cellfun('isclass', c, 'cell') | ...
                                                                   (~strings & ~scalar)));
  boolean = scalar & ~array & (cellfun('isclass', c, 'logical') | strcmp(types, 'boolean'));
  number = scalar & ~array & ~boolean & cellfun('isclass', c, 'double');
  if any(number(:))
    integer = strcmp(types, 'integer');
    texts(number) = number_texts([c{number}], integer(number));
  end
  if any(boolean(:))
    words = {'false', 'true'};
    texts(boolean) = words(([c{boolean}] ~= 0) + 1);
  end
  strings = strings & ~array;
  if any(strings(:))
    texts(strings) = quoted(c(strings));
  end
  others = find(cellfun('isempty', texts));
  for k = reshape(others, 1, [])
    texts{k} = other_text(c{k}, schemas{1 + mod(k - 1, size(schemas, 1))});
  end
end

function text = other_text(value, schema)
  type = schema_type(schema);
  if isstruct(value) || iscell(value) || strcmp(type, 'array') || (isempty(type) && numel(value) ~= 1)
    text = encode(value, schema);
  elseif numel(value) ~= 1
    error('beft:json', 'a %dx%d %s where one %s is wanted', size(value, 1), size(value, 2), class(value), type);
  elseif isnumeric(value) && ~isfloat(value)
    text = sprintf('%d', value);  % an integer class
  elseif isnumeric(value)
    texts = number_texts(double(value), strcmp(type, 'integer'));
    text = texts{1};
  else
    error('beft:json', 'cannot write a %s as JSON', class(value));
  end
end

% Doubles as text that reads back to the same bits: 17 significant
% digits (an integral value below 1e17 comes out as an integer), -0 as
% -0.0 (as -0 it would read back as the integer 0), non-finite as null.
function texts = number_texts(x, integer)
  x = x(:);
  integer = integer(:);
  texts = regexp(sprintf('%.17g\n', x), '\n', 'split');
  texts = reshape(texts(1:numel(x)), [], 1);
  zero = x == 0;
  texts(zero & (integer | 1 ./ x > 0)) = {'0'};
  texts(zero & ~integer & 1 ./ x < 0) = {'-0.0'};
  texts(~isfinite(x)) = {'null'};
  big = find(integer & isfinite(x) & abs(x) >= 1e17 & x == fix(x));
  for k = reshape(big, 1, [])
    texts{k} = sprintf('%.0f', x(k));  % an integer member, not 1e+17
  end
end

% JSON strings: quote, backslash and control characters escaped.
function texts = quoted(values)
  texts = regexprep(values, '(["\\])', '\\$1');
  control = find(~cellfun('isempty', regexp(texts, '[\x00-\x1f]', 'once')));
  for k = reshape(control, 1, [])
    low = texts{k} < 32;
    parts = num2cell(texts{k});
    parts(low) = arrayfun(@(c) sprintf('\\u%04x', c), double(texts{k}(low)), 'UniformOutput', false);
    texts{k} = [parts{:}];
  end
  quotes = regexp(sprintf(['"%s"' char(1)], texts{:}), char(1), 'split');
  texts(:) = quotes(1:numel(texts));
end

function type = schema_type(schema)
  type = '';
  if isstruct(schema) && isfield(schema, 'type')
    type = schema.type;
  end
end

function items = schema_items(schema)
  items = [];
  if isstruct(schema) && isfield(schema, 'items')
    items = schema.items;
  end
end
