function failures = test_json()
% The MATLAB/Octave client's numbers (modules/matlab): doubles through its
% JSON encoder and decoder bit for bit, the bridge's null as NaN, members
% an array, an integer or a boolean by the schema, and C's fmod where the
% geometry's angles need it. Returns the number of failed checks; run by
% run_octave.sh (ctest matlab_client) with the client's jar in BEFT_MATLAB_JAR.
  here = fileparts(mfilename('fullpath'));
  addpath(fullfile(here, '..', '..', '..', 'modules', 'matlab', 'beft'));
  javaaddpath(getenv('BEFT_MATLAB_JAR'));
  failures = 0;

  % Awkward doubles (and random bit patterns) written and read back exactly.
  awkward = [0.1, 1/3, 5e-324, 1.7976931348623157e308, -0.0, 0.0, 2.2250738585072014e-308, -1e-310, ...
             0.30000000000000004, 933.1286246343909, 2^53, 2^53 + 2, 1e17, 1e20, -123456.789, pi, exp(1)];
  rng(7);
  bits = [typecast(uint64(randi(2^52, 1, 4000)) * uint64(4093), 'double'), awkward];
  bits = bits(isfinite(bits));
  text = beft_json_encode(struct('x', bits));
  back = beft_json_decode(text);
  failures = check(failures, same_bits(back.x, bits(:)), 'doubles written and read back bit for bit');
  failures = check(failures, ~isempty(strfind(text, '-0.0,')), '-0 is written as -0.0');

  % NaN and the infinities are null, read back as NaN; a lone null too.
  back = beft_json_decode(beft_json_encode(struct('a', [1, NaN, Inf, -Inf], 'b', NaN)));
  failures = check(failures, isequal(isnan(back.a), [false; true; true; true]) && isnan(back.b), 'null is NaN');

  % The bridge writes the shortest text that reads back the same; Octave's
  % own jsondecode misreads some (RapidJSON without full precision).
  failures = check(failures, same_bits(beft_json_decode('[933.1286246343909]'), hex2num('408d29076c5a315a')), ...
                   'shortest text read exactly (jsondecode alone is one ULP off here)');
  failures = check(failures, same_bits(beft_json_decode('{"v":[0.1,5e-324,1.7976931348623157e+308]}').v, ...
                                       hex2num({'3fb999999999999a'; '0000000000000001'; '7fefffffffffffff'})), ...
                   'shortest texts of 0.1, the least subnormal and the largest double');

  % A text of small integers only is read by jsondecode as it is; -0 is not one of them.
  plain = beft_json_decode('{"tick":12,"ids":[1,2,3],"z":-0}');
  failures = check(failures, isequal(plain.ids, [1; 2; 3]) && plain.tick == 12 && 1 / plain.z == -Inf, ...
                   'integers read as they are, -0 kept');

  % Strings with quotes, backslashes and control characters, and numbers in them, untouched.
  s = struct('t', sprintf('a"b\\c\td 1.5e3 null'), 'u', '');
  failures = check(failures, isequal(beft_json_decode(beft_json_encode(s)), s), 'strings round trip');

  % The schema the bridge advertises: one element is still an array, -0 an
  % integer 0, 1 a boolean true.
  schema = jsondecode(['{"type":"object","properties":{"n":{"type":"integer"},"d":{"type":"number"},' ...
                       '"b":{"type":"boolean"},"v":{"type":"array","items":{"type":"number"}},' ...
                       '"o":{"type":"array","items":{"type":"object","properties":{"k":{"type":"integer"}}}}}}']);
  text = beft_json_encode(struct('n', -0, 'd', -0, 'b', 1, 'v', 2.5, 'o', struct('k', 7)), schema);
  failures = check(failures, strcmp(text, '{"n":0,"d":-0.0,"b":true,"v":[2.5],"o":[{"k":7}]}'), ['schema: ' text]);
  text = beft_json_encode(struct('n', 1e20, 'v', [], 'o', struct('k', {})), schema);
  failures = check(failures, strcmp(text, '{"n":100000000000000000000,"v":[],"o":[]}'), ['schema, empty: ' text]);
  text = beft_json_encode(struct('list', {{'x'}}, 'one', struct('a', {1, 2}), 'flag', false));
  failures = check(failures, strcmp(text, '{"list":["x"],"one":[{"a":1},{"a":2}],"flag":false}'), ['no schema: ' text]);

  % A value the schema has no place for is refused, not written.
  try
    beft_json_encode(struct('n', [1, 2]), schema);
    failures = check(failures, false, 'two numbers where the schema wants one: refused');
  catch err
    failures = check(failures, strcmp(err.identifier, 'beft:json'), ['refused as: ' err.message]);
  end

  % C's fmod (values from C), which rem is not: rem(0.3, 0.1) is 0.
  cases = {0.3, 0.1, '3fb9999999999998'; hex2num('41b5752e37ffffff'), 360, '40767ffffff00000'
           -725.5, 360, 'c016000000000000'; -360, 360, '8000000000000000'; 719.9999999999999, 360, '40767ffffffffffe'};
  for k = 1:size(cases, 1)
    failures = check(failures, same_bits(beft_fmod(cases{k, 1}, cases{k, 2}), hex2num(cases{k, 3})), ...
                     sprintf('fmod(%.17g, %g)', cases{k, 1}, cases{k, 2}));
  end
  failures = check(failures, beft_wrap_degrees(540) == 180 && beft_wrap_degrees(-180) == 180, ...
                   'wrap into (-180, 180]');

  if failures == 0
    fprintf('test_json: all checks passed\n');
  end
end

function failures = check(failures, ok, what)
  if ~ok
    fprintf(2, 'FAILED: %s\n', what);
    failures = failures + 1;
  end
end

function same = same_bits(a, b)
  same = isequal(size(a), size(b)) && strcmp(reshape(num2hex(a(:)), 1, []), reshape(num2hex(b(:)), 1, []));
end
