; step_loop_asm: the inner loop of persp-subdiv-N and constant-depth, one piece between exact
; points; twin of kernel/mappers/subdiv.cpp (step_loop), which it matches bit for bit: the texel
; at (u >> 16, v >> 16), wrapped as texel() wraps (by `and` for a power-of-two size, else by the
; remainder made non-negative) or clamped, then u += du, v += dv, wrapping as 32-bit adds do.

bits 32

%include "subdiv.inc"
%include "loop.inc"

section .text

; wrap or clamp eax into [0, size) as texel() does; %1: the size's field, %2: its mask's field,
; %3: a unique label prefix; clobbers edx
%macro WRAP 3
    cmp dword [ebx + STEP_clamp], 0
    jne %3_clamp
    mov edx, [ebx + %2]
    test edx, edx
    jz %3_divide
    and eax, edx                    ; a power of two: two's complement wraps negatives too
    jmp %3_done
%3_divide:
    cdq
    idiv dword [ebx + %1]           ; edx = remainder, with the dividend's sign
    mov eax, edx
    test eax, eax
    jns %3_done
    add eax, [ebx + %1]
    jmp %3_done
%3_clamp:
    test eax, eax
    jns %3_not_negative
    xor eax, eax
%3_not_negative:
    cmp eax, [ebx + %1]
    jl %3_done
    mov eax, [ebx + %1]
    dec eax
%3_done:
%endmacro

global step_loop_asm
step_loop_asm:
    LOOP_ENTER 4                    ; [esp]: v
    mov ebx, LOOP_ARG(4)
    ; ebx: args (read only); edi: destination; esi: u; ebp: pixels left
    mov edi, [ebx + STEP_dst]
    mov esi, [ebx + STEP_u_16_16]
    mov eax, [ebx + STEP_v_16_16]
    mov [esp], eax
    mov ebp, [ebx + STEP_count]
    test ebp, ebp
    jle .done
.pixel:
    mov eax, [esp]
    sar eax, 16                     ; floor(v)
    WRAP STEP_height, STEP_height_mask, .wv
    imul eax, [ebx + STEP_width]
    mov ecx, eax                    ; ecx = row * width
    mov eax, esi
    sar eax, 16                     ; floor(u)
    WRAP STEP_width, STEP_width_mask, .wu
    add eax, ecx
    mov edx, [ebx + STEP_texels]
    mov al, [edx + eax]
    mov [edi], al
    add edi, [ebx + STEP_stride]
    add esi, [ebx + STEP_du_16_16]
    mov eax, [ebx + STEP_dv_16_16]
    add [esp], eax
    dec ebp
    jnz .pixel
.done:
    LOOP_LEAVE 4
