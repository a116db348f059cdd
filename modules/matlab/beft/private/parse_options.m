function options = parse_options(expert, args)
% The command line of an expert (the Python and C++ experts' options):
% --opt VALUE or --opt=VALUE. Errors (identifier beft:usage) name what is
% wrong.
  url = getenv('BEFT_BRIDGE_URL');
  if isempty(url)
    url = 'ws://127.0.0.1:8765';
  end
  options = struct('help', false, 'interface', false, 'url', url, 'name', expert.name, 'param', {{}}, ...
                   'heartbeat_period', 0.5, 'ready_timeout', 0, 'connect_timeout', 30, 'resume_log', '');
  i = 1;
  while i <= numel(args)
    [flag, value, has_value] = split_option(args{i});
    switch flag
      case {'-h', '--help'}
        options.help = true;
      case '--interface'
        options.interface = true;
      case {'--url', '--name', '--resume-log', '--lcm-url', '--param', '--heartbeat-period', '--ready-timeout', ...
            '--connect-timeout'}
        if ~has_value
          if i == numel(args)
            error('beft:usage', 'argument %s: expected one argument', flag);
          end
          i = i + 1;
          value = args{i};
        end
        options = set_option(options, flag, value);
      otherwise
        error('beft:usage', 'unrecognized arguments: %s', args{i});
    end
    i = i + 1;
  end
end

function [flag, value, has_value] = split_option(arg)
  equals = strfind(arg, '=');
  has_value = strncmp(arg, '--', 2) && ~isempty(equals);
  if has_value
    flag = arg(1:equals(1) - 1);
    value = arg(equals(1) + 1:end);
  else
    flag = arg;
    value = '';
  end
end

function options = set_option(options, flag, value)
  switch flag
    case '--param'
      options.param{end + 1} = value;
    case '--lcm-url'
      % accepted and unused: the bridge publishes on the run's LCM
    case {'--heartbeat-period', '--ready-timeout', '--connect-timeout'}
      number = str2double(value);
      if ~isfinite(number) || number < 0
        error('beft:usage', 'argument %s: invalid value: ''%s''', flag, value);
      end
      options.(strrep(flag(3:end), '-', '_')) = number;
    otherwise
      options.(strrep(flag(3:end), '-', '_')) = value;
  end
end
